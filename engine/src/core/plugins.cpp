// Plug-in laws (plugin.hpp): loaded with dlopen, kept for the life of the program.
#include <dlfcn.h>

#include <algorithm>
#include <mutex>
#include <set>
#include <stdexcept>

#include "tessera/plugin.hpp"

namespace tessera {

namespace {

struct Loaded : LawRegistry {
  std::vector<std::unique_ptr<JointLaw>> joints;
  std::vector<std::unique_ptr<ZoneModel>> zones;
  std::set<std::string> files;
  std::vector<std::string> added;  // names registered by the load in progress
  void add_joint_law(std::unique_ptr<JointLaw> law) override {
    if (!law) return;
    added.emplace_back(law->name());
    joints.push_back(std::move(law));
  }
  void add_zone_model(std::unique_ptr<ZoneModel> model) override {
    if (!model) return;
    added.emplace_back(model->name());
    zones.push_back(std::move(model));
  }
};

Loaded& loaded() {
  static Loaded l;
  return l;
}
std::mutex& guard() {
  static std::mutex m;
  return m;
}

}  // namespace

std::vector<std::string> load_plugin(const std::string& path) {
  std::lock_guard<std::mutex> lock(guard());
  Loaded& l = loaded();
  if (l.files.count(path)) return {};
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw std::runtime_error(path + ": cannot load the plug-in (" + dlerror() + ")");
  using Register = void (*)(LawRegistry&);
  auto reg = reinterpret_cast<Register>(dlsym(handle, "tessera_register"));
  if (!reg) throw std::runtime_error(path + ": not a Tessera plug-in (no tessera_register)");
  // Names already taken, built in or loaded before.
  std::set<std::string> taken;
  for (const std::string& n : joint_law_names()) taken.insert(n);
  for (const std::string& n : zone_model_names()) taken.insert(n);
  const size_t joints0 = l.joints.size(), zones0 = l.zones.size();
  l.added.clear();
  reg(l);
  std::vector<std::string> added = l.added;
  const auto undo = [&] {
    l.joints.resize(joints0);
    l.zones.resize(zones0);
  };
  if (added.empty()) {
    undo();
    throw std::runtime_error(path + ": the plug-in registered no law");
  }
  for (const std::string& n : added)
    if (!taken.insert(n).second) {
      undo();
      throw std::runtime_error(path + ": the plug-in's law '" + n + "' has a name taken already");
    }
  l.files.insert(path);
  return added;
}

const JointLaw* plugin_joint_law(const std::string& name) {
  for (const auto& law : loaded().joints)
    if (name == law->name()) return law.get();
  return nullptr;
}

const ZoneModel* plugin_zone_model(const std::string& name) {
  for (const auto& model : loaded().zones)
    if (name == model->name()) return model.get();
  return nullptr;
}

std::vector<std::string> plugin_law_names(bool zones) {
  std::vector<std::string> out;
  if (zones)
    for (const auto& z : loaded().zones) out.emplace_back(z->name());
  else
    for (const auto& j : loaded().joints) out.emplace_back(j->name());
  return out;
}

}  // namespace tessera
