// -lub_* options: parsing, defaults, and errors that name the option.
#include "vp/core/Error.hpp"
#include "vp/interactions/LubricationOptions.hpp"
#include <catch2/catch.hpp>
#include <petscsys.h>
#include <string>
#include <vector>

using namespace vp;

namespace {

// Sets options for one test and removes them afterwards (the database is shared by all tests).
struct ScopedOptions {
  ScopedOptions(std::initializer_list<std::pair<const char*, const char*>> kv) : kv_(kv)
  {
    for (auto& [k, v] : kv_) PetscOptionsSetValue(nullptr, k, v);
  }
  ~ScopedOptions()
  {
    for (auto& [k, v] : kv_) PetscOptionsClearValue(nullptr, k);
  }
  std::vector<std::pair<const char*, const char*>> kv_;
};

std::string errorOf(std::initializer_list<std::pair<const char*, const char*>> kv)
{
  ScopedOptions o{kv};
  try {
    readLubricationOptions();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST_CASE("Lubrication options: defaults and values", "[lub]")
{
  {
    const LubricationParams p = readLubricationOptions();
    CHECK(p.model == LubModel::None);
    CHECK(p.activation == 0);
    CHECK(p.saturation == 0);
    CHECK(p.llcmRegion == 1);
  }
  ScopedOptions o{{"-lub_model", "llcm"}, {"-lub_activation", "0.1"}, {"-lub_saturation", "4e-4"}, {"-lub_llcm_r0", "0.5"}};
  const LubricationParams p = readLubricationOptions();
  CHECK(p.model == LubModel::Llcm);
  CHECK(p.activation == 0.1);
  CHECK(p.saturation == 4e-4);
  CHECK(p.llcmRegion == 0.5);
}

TEST_CASE("Lubrication options: bad values name the option and the range", "[lub]")
{
  CHECK(errorOf({{"-lub_model", "stokes"}}) == "option -lub_model: unknown value 'stokes' (valid: none, blcm, llcm)");
  CHECK(errorOf({{"-lub_activation", "-1"}}).rfind("option -lub_activation: must be >= 0", 0) == 0);
  CHECK(errorOf({{"-lub_saturation", "-1e-3"}}).rfind("option -lub_saturation: must be >= 0", 0) == 0);
  CHECK(errorOf({{"-lub_activation", "0.01"}, {"-lub_saturation", "0.02"}}) ==
        "option -lub_saturation: must be below -lub_activation (0.01), got 0.02");
  CHECK(errorOf({{"-lub_llcm_r0", "0"}}) == "option -lub_llcm_r0: must be > 0, got 0");
  CHECK(errorOf({{"-lub_inertia", "true"}}) ==
        "option -lub_inertia: corrects the lubrication's squeeze: it needs -lub_model blcm or llcm");
  CHECK(errorOf({{"-lub_coupling", "swap"}}) == "option -lub_coupling: unknown value 'swap' (valid: add, replace)");
  CHECK(errorOf({{"-lub_coupling", "replace"}}) ==
        "option -lub_coupling: replace applies the LLCM's inner solution over the gap's disk r < r0: it needs -lub_model llcm");
  CHECK(errorOf({{"-lub_coupling", "replace"}, {"-lub_model", "blcm"}}).rfind("option -lub_coupling: replace applies", 0) == 0);
  CHECK(errorOf({{"-lub_coupling", "replace"}, {"-lub_model", "llcm"}, {"-lub_patch_gap", "0.6"}}) ==
        "option -lub_patch_gap: must be in (0, 0.5]: the patch (r0^2 = 2 R delta) must fit within the sphere, got 0.6");
  CHECK(errorOf({{"-lub_model", "llcm"}, {"-lub_patch_gap", "0.3"}}) ==
        "option -lub_patch_gap: applies to -lub_coupling replace only");
  CHECK(errorOf({{"-lub_coupling", "replace"}, {"-lub_model", "llcm"}, {"-lub_patch_blend", "5"}}) ==
        "option -lub_patch_blend: must be in [0, 4] grid cells, got 5");
  CHECK(errorOf({{"-lub_model", "llcm"}, {"-lub_patch_blend", "0"}}) == "option -lub_patch_blend: applies to -lub_coupling replace only");
  CHECK(errorOf({{"-lub_coupling", "replace"}, {"-lub_model", "llcm"}, {"-lub_integration", "implicit"}}) ==
        "option -lub_integration: implicit takes the added squeeze; with -lub_coupling replace use explicit");
  CHECK(errorOf({{"-lub_shear_activation_cells", "-0.1"}}).rfind("option -lub_shear_activation_cells: must be >= 0", 0) == 0);
  CHECK(errorOf({{"-lub_activation", "0.05"}, {"-lub_shear_activation_cells", "0.05"}}) ==
        "option -lub_shear_activation_cells: give it with -lub_activation_cells, not -lub_activation, got 0.05");
}

TEST_CASE("Lubrication defaults resolved from the grid, the fluid and the roughness", "[lub]")
{
  LubricationParams p;
  p.model = LubModel::Blcm;
  p.resolveDefaults(1e-4, true, 4e-4); // coupled: activation 0.18 cells; saturation from the roughness
  CHECK(p.resolved());
  CHECK(p.activationCells == kDefaultActivationCells);
  CHECK(p.activationGap(1e-3) == Approx(0.18e-4).epsilon(1e-15));
  CHECK(p.activationGap(5e-4) == p.activationGap(1e-3));
  CHECK(p.saturation == 4e-4);
  LubricationParams q;
  q.model = LubModel::Blcm;
  CHECK_THROWS_WITH(q.resolveDefaults(1e-4, false, 4e-4), "option -lub_activation: must be > 0 (gap over radius), got 0 "
                                                         "(DEM-only runs set -lub_activation or -lub_activation_cells)");
  LubricationParams r;
  r.model = LubModel::Llcm;
  r.activation = 0.01;
  CHECK_THROWS_WITH(r.resolveDefaults(1e-4, true, 0.05), "option -lub_saturation: must be in (0, -lub_activation = 0.01), got 0.05");
  CHECK(r.activationGap(2e-3) == Approx(2e-5).epsilon(1e-15));  // eps_act given: per pair radius
  LubricationParams v;  // replace: its own default activation gap, the tangential terms' unchanged
  v.model = LubModel::Llcm;
  v.replace = true;
  v.resolveDefaults(1e-4, true, 4e-4);
  CHECK(v.activationCells == kDefaultReplacementCells);
  CHECK(v.shearActivationCells == kDefaultShearActivationCells);
  LubricationParams u;
  u.model = LubModel::Llcm;
  u.replace = true;
  u.activationCells = 1;
  CHECK_THROWS_WITH(u.resolveDefaults(1e-4, false, 4e-4), Catch::StartsWith("option -lub_coupling: replace takes the gap patch "
                                                                           "out of the resolved force: it needs a fluid"));
  LubricationParams t;
  t.model = LubModel::Llcm;
  t.activationCells = 1;
  t.saturation = 0.2;  // 0.2 a = 2e-4 m for a = 1e-3 m: above the 1-cell activation gap
  t.resolveDefaults(1e-4, true, 4e-4);  // the gap depends on the particles: checked against them
  CHECK_THROWS_WITH(t.checkRadius(1e-3), Catch::Contains("option -lub_saturation: the saturation gap 0.2 a must be below the activation gap"));
  CHECK_NOTHROW(t.checkRadius(4e-4));
}
