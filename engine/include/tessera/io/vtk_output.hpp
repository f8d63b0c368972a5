// ParaView output: VTK XML PolyData files (.vtp) per snapshot, gathered by .pvd collections;
// the tetrahedral zones of 3D models as UnstructuredGrid files (.vtu).
//
// Written as plain XML text by hand: the engine does not link VTK.
#pragma once

#include <string>
#include <vector>

#include "tessera/core/model.hpp"

namespace tessera {

class VtkSeries {
 public:
  // Files go to `dir` (created if missing): blocks.pvd, contacts.pvd (zones.pvd once there are
  // deformable blocks, support.pvd once there are bolts) and one .vtp of each per snapshot (.vtu
  // for 3D zones).
  explicit VtkSeries(std::string dir);
  // Writes a snapshot of the model; throws std::runtime_error naming the file on failure.
  void write(const Model& m);
  size_t frames() const { return times_.size(); }
  const std::string& dir() const { return dir_; }

 private:
  void write_collection(const std::string& name, size_t first = 0, const char* ext = "vtp") const;
  std::string dir_;
  std::vector<double> times_;      // of every snapshot written
  std::vector<size_t> listed_;     // the snapshots the collections list, their times rising
  int zones_from_ = -1;            // first snapshot with zones
  int support_from_ = -1;          // first snapshot with bolts
  const char* zones_ext_ = "vtp";  // 2D zones are PolyData, 3D zones an UnstructuredGrid (.vtu)
};

// Contact state code used in the output: 0 open, 1 elastic, 2 slipping, 3 bonded.
int contact_state_code(uint8_t flags);

}  // namespace tessera
