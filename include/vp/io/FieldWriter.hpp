#pragma once
// Field snapshots: fields_<step>.h5 (parallel HDF5 through PetscViewerHDF5; datasets velocity
// (cell-centred, nz x ny x nx x 3), pressure (nz x ny x nx) and, with particles, chi (the solid
// fraction at cell centres, mean of the six faces' mask); root attributes time, step, origin
// and spacing (x, y, z order)) and fields.xmf, a temporal collection of 3DCoRectMesh grids with
// relative paths that ParaView opens. See docs/outputs.md.
#include "vp/grid/Grid.hpp"
#include <string>
#include <vector>

namespace vp {

class FieldWriter {
public:
  FieldWriter(const Grid& grid, std::string dir);
  ~FieldWriter();
  FieldWriter(const FieldWriter&) = delete;
  FieldWriter& operator=(const FieldWriter&) = delete;

  // velocityLocal: faceDM local vector with ghosts filled; pressure: cellDM global vector;
  // chi: the particles' mask on the faces (faceDM global vector), or null without particles.
  void write(int step, double time, Vec velocityLocal, Vec pressure, Vec chi = nullptr);

  // The snapshots so far as (step, time) pairs (rank 0, which writes fields.xmf), and their
  // restoration on a restart: those whose files are in the output directory stay in fields.xmf.
  std::vector<double> snapshotList() const;
  void resume(const std::vector<double>& list);

private:
  void writeXdmf(bool chi) const;

  const Grid& grid_;
  std::string dir_;
  Vec centre_ = nullptr, chiCell_ = nullptr, chiLocal_ = nullptr;
  std::vector<std::pair<int, double>> snapshots_;
};

} // namespace vp
