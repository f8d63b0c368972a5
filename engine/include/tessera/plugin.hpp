// Joint laws and zone models of your own, loaded at run time by `model load FILE.so`.
//
// A plug-in is a shared library that defines one function with C linkage,
//
//   TESSERA_PLUGIN { registry.add_joint_law(std::make_unique<MyLaw>()); }
//
// which registers laws by their name(): `joint define ... law=NAME` and `material define ...
// model=NAME` then use them as the built-in ones. A law's update() is called for every contact
// (zone) every cycle, from several threads at once: it must only read its properties and write
// the state it is given. The plug-in needs this header and the two it includes, nothing to link:
// see examples/plugins/ for one built with CMake.
#pragma once

#include <memory>

#include "tessera/core/joint_law.hpp"
#include "tessera/zones/zone_model.hpp"

namespace tessera {

// What a plug-in registers its laws with; Tessera keeps them for the life of the program.
class LawRegistry {
 public:
  virtual ~LawRegistry() = default;
  virtual void add_joint_law(std::unique_ptr<JointLaw> law) = 0;
  virtual void add_zone_model(std::unique_ptr<ZoneModel> model) = 0;
};

// Loads a plug-in and registers its laws; returns their names. Loading the same file again
// registers nothing. Throws std::runtime_error naming the file: it cannot be loaded, it has no
// tessera_register, it registers nothing, or a name is taken already.
std::vector<std::string> load_plugin(const std::string& path);

// The laws plug-ins registered (nullptr if none has the name).
const JointLaw* plugin_joint_law(const std::string& name);
const ZoneModel* plugin_zone_model(const std::string& name);
std::vector<std::string> plugin_law_names(bool zones);

}  // namespace tessera

// The function every plug-in defines.
#define TESSERA_PLUGIN                                                     \
  extern "C" __attribute__((visibility("default"))) void tessera_register( \
      tessera::LawRegistry& registry)
