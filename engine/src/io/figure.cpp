// Names of the figure and view options, shared by scripts and the GUI.
#include "tessera/io/figure.hpp"

namespace tessera {

const std::vector<std::string>& colour_by_names() {
  static const std::vector<std::string> names{
      "group", "material", "displacement", "xdisp", "ydisp",  "zdisp",  "velocity", "rotation",
      "sxx",   "syy",      "sxy",          "szz",   "sigma1", "sigma3", "state"};
  return names;
}

const std::vector<std::string>& contact_show_names() {
  static const std::vector<std::string> names{"off", "state", "stress", "shear"};
  return names;
}

namespace {
template <typename E>
bool parse_name(const std::vector<std::string>& names, const std::string& word, E& e) {
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == word) return e = static_cast<E>(i), true;
  return false;
}
}  // namespace

bool parse_colour_by(const std::string& word, ColourBy& c) {
  return parse_name(colour_by_names(), word, c);
}

bool parse_contact_show(const std::string& word, ContactShow& c) {
  // `force`: the name before the bars showed stress (a script of then draws the same picture).
  if (word == "force") return c = ContactShow::kStress, true;
  return parse_name(contact_show_names(), word, c);
}

std::string set_perspective(ViewOptions& v, const std::string& word, int dim) {
  if (dim != 3) return "perspective= draws 3D models in perspective; this model is 2D";
  if (word != "on" && word != "off") return "write perspective=on or perspective=off";
  v.perspective = word == "on";
  return {};
}

}  // namespace tessera
