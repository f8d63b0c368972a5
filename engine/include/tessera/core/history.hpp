// Histories: quantities sampled every `interval` cycles, written as CSV columns.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace tessera {

struct Model;

enum class HistoryQuantity : uint8_t {
  kXDisp,
  kYDisp,
  kXVel,
  kYVel,
  kRotation,
  kAngVel,
  kXPos,
  kYPos,  // of one block
  kRatio,
  kUnbalanced,
  kKinetic,
  kTime,
  kTimestep,  // of the model
  kZDisp,
  kZVel,
  kZPos,  // of a block of a 3D model
  kSxx,
  kSyy,
  kSzz,
  kSxy,
  kSyz,
  kSxz,
  kSigma1,
  kSigma3,  // of one zone (tension positive; sigma1 the most compressive)
  kBoltAxial,
  kBoltShear,  // at one crossing of a bolt (axial: tension positive)
  kCableAxial,
  kCableSlip,  // at one node of a cable (its segment's force, tension positive; grout slip)
  kLinerThrust,
  kLinerMoment,
  kLinerPressure,  // at one node of a liner (its elements' thrust, compression positive, and
                   // moment at the node; the interface's pressure on the rock)
  kSlipping,       // of the model: contacts (3D: sub-contacts) slipping this cycle
  kNormalForce,
  kShearForce  // between two blocks (block and element hold their indices): the sum of their
               // contacts' normal forces (compression positive) and the size of the resultant
               // shear force
};

struct HistorySeries {
  HistoryQuantity quantity = HistoryQuantity::kRatio;
  int32_t block = -1;    // block index for block quantities
  int32_t node = -1;     // continuum node, when the block is deformable
  std::string label;     // CSV column heading
  int32_t zone = -1;     // zone for zone quantities (-1 once it is deleted)
  int32_t element = -1;  // bolt element or cable node for support quantities (-1: gone), the
                         // second block of a contact quantity (-2: deleted)
};

struct Histories {
  uint32_t interval = 10;
  std::vector<HistorySeries> series;
  std::vector<uint64_t> cycles;  // cycle of each sample
  std::vector<double> values;    // row-major: one row per sample, one column per series
  size_t columns() const { return series.size(); }
  size_t rows() const { return cycles.size(); }
  double at(size_t row, size_t col) const { return values[row * series.size() + col]; }
  // Column index of a label, or -1.
  int find(const std::string& label) const;
};

// Contacts (3D: sub-contacts) at their shear strength this cycle.
size_t slipping_contacts(const Model& m);

// Quantity by script keyword, true if known; `block_quantity` says whether it needs a block.
bool parse_history_quantity(const std::string& word, HistoryQuantity& q, bool& block_quantity);
const char* history_quantity_name(HistoryQuantity q);
// Its unit ("" for the ratio): per metre of thickness in 2D for forces and energies.
std::string history_quantity_unit(HistoryQuantity q, int dim);
// Whether a quantity is a zone's stress (sampled in one zone, picked by a point).
bool is_zone_quantity(HistoryQuantity q);
// Whether a quantity is a bolt's force (sampled at one crossing, picked by bolt and point).
bool is_bolt_quantity(HistoryQuantity q);
// Whether a quantity is a cable's (sampled at one node, picked by cable and point).
bool is_cable_quantity(HistoryQuantity q);
// Whether a quantity is a liner's (sampled at one node, picked by liner and point).
bool is_liner_quantity(HistoryQuantity q);
// Whether a quantity is a force between two blocks (picked by contact=A,B).
bool is_contact_quantity(HistoryQuantity q);
// Every quantity's keyword, for messages.
std::vector<std::string> history_quantity_names();
// Current value of one series.
double history_value(const Model& m, const HistorySeries& s);
// Samples all series if the model's cycle is on the interval (or always when forced).
void sample_histories(Model& m, bool force = false);
// CSV with a header row: cycle, then one column per series.
void write_histories_csv(const Histories& h, std::ostream& out);

}  // namespace tessera
