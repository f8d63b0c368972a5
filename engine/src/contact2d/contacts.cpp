#include "tessera/contact2d/contacts.hpp"

namespace tessera {

void Contacts::clear() {
  for_each_array([](auto& v) { v.clear(); });
  each_optional([](auto& v) { v.clear(); }, *this);
  pair_begin.assign(1, 0);
  pair_force.clear(), pair_moment.clear(), pair_load.clear();
}

void Contacts::push_from(const Contacts& s, size_t i) {
  each_array([i](auto& to, const auto& from) { to.push_back(from[i]); }, *this, s);
  // An optional array is copied when the source holds it (every contact then comes from s).
  each_optional(
      [i](auto& to, const auto& from) {
        if (!from.empty()) to.push_back(from[i]);
      },
      *this, s);
}

}  // namespace tessera
