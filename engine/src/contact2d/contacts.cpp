#include "tessera/contact2d/contacts.hpp"

namespace tessera {

void Contacts::clear() {
  for_each_array([](auto& v) { v.clear(); });
  pair_begin.assign(1, 0);
}

void Contacts::push_from(const Contacts& s, size_t i) {
  each_array([i](auto& to, const auto& from) { to.push_back(from[i]); }, *this, s);
}

}  // namespace tessera
