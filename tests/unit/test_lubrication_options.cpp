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
    readLubricationOptions(PETSC_COMM_SELF);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST_CASE("Lubrication options: defaults and values", "[lub]")
{
  {
    const LubricationParams p = readLubricationOptions(PETSC_COMM_SELF);
    CHECK(p.model == LubModel::None);
    CHECK(p.activation == 0);
    CHECK(p.saturation == 0);
    CHECK(p.llcmRegion == 1);
  }
  ScopedOptions o{{"-lub_model", "llcm"}, {"-lub_activation", "0.1"}, {"-lub_saturation", "4e-4"}, {"-lub_llcm_r0", "0.5"}};
  const LubricationParams p = readLubricationOptions(PETSC_COMM_SELF);
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
}

TEST_CASE("Lubrication parameters completed by the caller", "[lub]")
{
  LubricationParams p;
  p.model = LubModel::Blcm;
  p.complete(0.2, 4e-4); // activation from the grid, saturation from the roughness
  CHECK(p.activation == 0.2);
  CHECK(p.saturation == 4e-4);
  LubricationParams q;
  q.model = LubModel::Blcm;
  CHECK_THROWS_WITH(q.complete(0, 4e-4), "option -lub_activation: must be > 0 (gap over radius), got 0");
  LubricationParams r;
  r.model = LubModel::Llcm;
  r.activation = 0.01;
  CHECK_THROWS_WITH(r.complete(0.2, 0.05), "option -lub_saturation: must be in (0, -lub_activation = 0.01), got 0.05");
}
