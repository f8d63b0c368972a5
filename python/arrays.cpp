// The model's arrays as numpy arrays: one table per group (m.blocks, m.contacts, m.subcontacts,
// m.zones, m.nodes), one line per array saying how it is made from the engine's storage.
//
// A view shows the engine's own memory (read-only; its rows may be strided through a struct),
// a copy is made where the engine keeps the values apart (2D x and y) or computes them. When the
// engine's storage changes shape, only the line of the array concerned changes here.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <type_traits>

#include "bindings.hpp"
#include "tessera/contact3d/subcontacts.hpp"
#include "tessera/core/history.hpp"

namespace tessera::python {

namespace {

// Read-only: views show the engine's memory, which only named methods and commands change.
py::array frozen(py::array a) {
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

// n rows of k values of type T (k = 0: a 1D array) starting at p, rows `stride` bytes apart.
template <class T>
py::array view(const T* p, size_t n, size_t k, size_t stride, py::handle base) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(n)};
  std::vector<py::ssize_t> strides{static_cast<py::ssize_t>(stride)};
  if (k > 0) shape.push_back(static_cast<py::ssize_t>(k)), strides.push_back(sizeof(T));
  if (n == 0) return py::array(py::dtype::of<T>(), shape, strides);
  py::array a(py::dtype::of<T>(), shape, strides, p, base);
  // The window's model (borrowed) changes under Python's feet (undo, a failed command's
  // rollback, a script opened), so its arrays are copies, never views.
  if (!base.cast<const PyModel&>().owned) a = a.attr("copy")();
  return frozen(a);
}

template <class T>
constexpr size_t columns() {
  if constexpr (std::is_arithmetic_v<T>)
    return 0;
  else
    return static_cast<size_t>(T::RowsAtCompileTime);
}
template <class T>
const auto* first_value(const T& v) {
  if constexpr (std::is_arithmetic_v<T>)
    return &v;
  else
    return v.data();
}

// A view of a whole vector (scalars, or Eigen vectors as rows).
template <class T>
py::array whole(const std::vector<T>& v, py::handle base) {
  return view(v.empty() ? nullptr : first_value(v[0]), v.size(), columns<T>(), sizeof(T), base);
}
// A view of one member of a vector of structs.
template <class S, class M>
py::array member(const std::vector<S>& v, M S::*field, py::handle base) {
  return view(v.empty() ? nullptr : first_value(v[0].*field), v.size(), columns<M>(), sizeof(S),
              base);
}
// A fresh array of n rows of k values (k = 0: 1D), filled by fill(i, row pointer).
template <class T, class F>
py::array copy(size_t n, size_t k, F&& fill) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(n)};
  if (k > 0) shape.push_back(static_cast<py::ssize_t>(k));
  py::array_t<T> a(shape);
  T* p = a.mutable_data();
  for (size_t i = 0; i < n; ++i) fill(i, p + i * std::max<size_t>(k, 1));
  return a;
}

// Block values as the histories read them (a zoned block's from its nodes, a piece of a
// concave 3D block's from its body).
py::array block_values(const Model& m, std::initializer_list<HistoryQuantity> qs) {
  const size_t k = qs.size() == 1 ? 0 : qs.size();
  return copy<double>(m.block_count(), k, [&](size_t b, double* row) {
    HistorySeries s;
    s.block = static_cast<int32_t>(b);
    for (HistoryQuantity q : qs) s.quantity = q, *row++ = history_value(m, s);
  });
}
// Whether every 3D block moves as its own rigid body (then its body's arrays are its own).
bool plain_bodies(const Model& m) {
  const Blocks3& B = m.blocks3;
  for (size_t b = 0; b < B.size(); ++b)
    if (B.deformable[b] || B.is_slave(b)) return false;
  return true;
}
using Q = HistoryQuantity;
py::array block_vectors(const Model& m, Q x, Q y, Q z) {
  return m.dim == 3 ? block_values(m, {x, y, z}) : block_values(m, {x, y});
}

// One array of a group: its name, what it holds, and how it is made.
using Make = py::array (*)(const Model&, py::handle base);
struct Spec {
  const char* name;
  const char* doc;
  Make make;
};

const Spec kBlocks[] = {
    {"id", "block numbers as scripts write them (view)",
     [](const Model& m, py::handle o) {
       return m.dim == 3 ? whole(m.blocks3.id, o) : whole(m.blocks.id, o);
     }},
    {"group", "group index of each block, into Model.groups (view)",
     [](const Model& m, py::handle o) {
       return m.dim == 3 ? whole(m.blocks3.group, o) : whole(m.blocks.group, o);
     }},
    {"pos", "centroids (n, dim), m (3D rigid blocks: view; else copy)",
     [](const Model& m, py::handle o) {
       if (m.dim == 3 && plain_bodies(m)) return member(m.blocks3.body, &RigidBody3::position, o);
       return block_vectors(m, Q::kXPos, Q::kYPos, Q::kZPos);
     }},
    {"vel", "velocities (n, dim), m/s (3D rigid blocks: view; else copy)",
     [](const Model& m, py::handle o) {
       if (m.dim == 3 && plain_bodies(m)) return member(m.blocks3.body, &RigidBody3::velocity, o);
       return block_vectors(m, Q::kXVel, Q::kYVel, Q::kZVel);
     }},
    {"disp", "displacements since each block was made or 'reset displacement' (n, dim), m (copy)",
     [](const Model& m, py::handle) { return block_vectors(m, Q::kXDisp, Q::kYDisp, Q::kZDisp); }},
    {"rot", "rotation (n,), rad: 2D counter-clockwise angle (view); 3D angle turned (copy)",
     [](const Model& m, py::handle o) {
       return m.dim == 3 ? block_values(m, {Q::kRotation}) : whole(m.blocks.theta, o);
     }},
    {"angvel", "angular velocity: 2D (n,) rad/s; 3D (n, 3) world vector (view)",
     [](const Model& m, py::handle o) {
       return m.dim == 3 ? whole(m.blocks3.omega, o) : whole(m.blocks.omega, o);
     }},
    {"mass", "masses (n,), kg (2D: per metre of thickness) (view)",
     [](const Model& m, py::handle o) {
       return m.dim == 3 ? member(m.blocks3.body, &RigidBody3::mass, o) : whole(m.blocks.mass, o);
     }},
    {"fixity", "fixity bits (n,): 2D x 1, y 2, rotation 4; 3D x 1, y 2, z 4, rotation 8 (view)",
     [](const Model& m, py::handle o) {
       return m.dim == 3 ? whole(m.blocks3.fixity, o) : whole(m.blocks.fixity, o);
     }},
    {"load",
     "loads at the centroids ('load', set_force) (n, dim): 2D N/m (copy); 3D N, on the "
     "body's first piece (view)",
     [](const Model& m, py::handle o) {
       if (m.dim == 3) return whole(m.blocks3.load_force, o);
       const Blocks& B = m.blocks;
       return copy<double>(B.size(), 2, [&](size_t b, double* row) {
         row[0] = B.load_fx[b], row[1] = B.load_fy[b];
       });
     }},
    {"load_moment", "moments of the loads: 2D (n,) N m/m; 3D (n, 3) N m (view)",
     [](const Model& m, py::handle o) {
       return m.dim == 3 ? whole(m.blocks3.load_moment, o) : whole(m.blocks.load_m, o);
     }},
};

// 3D contacts: sums over each contact's sub-contacts.
template <size_t K, class F>
py::array per_contact3(const Model& m, F&& value) {
  return copy<double>(m.contacts3.size(), K, [&](size_t i, double* row) {
    std::array<double, K == 0 ? 1 : K> sum{};
    for (const SubContact& s : m.contacts3[i].subs) value(m.contacts3[i], s, sum);
    std::copy(sum.begin(), sum.end(), row);
  });
}
py::array block_pairs(const Model& m) {
  const bool three = m.dim == 3;
  const size_t n = three ? m.contacts3.size() : m.contacts.size();
  return copy<int>(n, 2, [&](size_t i, int* row) {
    const uint32_t a = three ? m.contacts3[i].a : m.contacts.a[i];
    const uint32_t b = three ? m.contacts3[i].b : m.contacts.b[i];
    row[0] = three ? m.blocks3.id[a] : m.blocks.id[a];
    row[1] = three ? m.blocks3.id[b] : m.blocks.id[b];
  });
}

const Spec kContacts[] = {
    {"blocks", "the two block numbers (n, 2) (copy)",
     [](const Model& m, py::handle) { return block_pairs(m); }},
    {"normal_force", "normal force (n,), compression positive; 2D N/m (view), 3D N summed (copy)",
     [](const Model& m, py::handle o) {
       if (m.dim != 3) return whole(m.contacts.fn, o);
       return per_contact3<0>(
           m, [](const Contact3&, const SubContact& s, auto& sum) { sum[0] += s.fn; });
     }},
    {"shear_force",
     "shear force: 2D (n,) N/m (view); 3D (n, 3) world vector on the first block (copy)",
     [](const Model& m, py::handle o) {
       if (m.dim != 3) return whole(m.contacts.fs, o);
       return per_contact3<3>(m, [](const Contact3& c, const SubContact& s, auto& sum) {
         const Vec3 f = shear_force(c, s);
         for (int k = 0; k < 3; ++k) sum[k] += f[k];
       });
     }},
    {"normal", "unit normal from the second block towards the first (n, dim) (view)",
     [](const Model& m, py::handle o) {
       return m.dim == 3 ? member(m.contacts3, &Contact3::normal, o) : whole(m.contacts.normal, o);
     }},
    {"force", "force on the first block this cycle (n, dim): 2D (copy), 3D (view)",
     [](const Model& m, py::handle o) {
       if (m.dim == 3) return member(m.contacts3, &Contact3::force, o);
       const Contacts& C = m.contacts;
       return copy<double>(C.size(), 2, [&](size_t i, double* row) {
         const Vec2 f = C.force(i);
         row[0] = f.x(), row[1] = f.y();
       });
     }},
    {"gap", "gap (n,), m, negative when overlapping (view)",
     [](const Model& m, py::handle o) {
       return m.dim == 3 ? member(m.contacts3, &Contact3::gap, o) : whole(m.contacts.gap, o);
     }},
    {"state",
     "state bits (n,): BONDED 1, SLIPPING 2, TOUCHING 4, BROKEN 8; 2D (view), 3D any "
     "sub-contact's (copy)",
     [](const Model& m, py::handle o) {
       if (m.dim != 3) return whole(m.contacts.flags, o);
       return copy<uint8_t>(m.contacts3.size(), 0, [&](size_t i, uint8_t* row) {
         *row = 0;
         for (const SubContact& s : m.contacts3[i].subs) *row |= s.flags;
       });
     }},
};

// 3D sub-contacts, flattened in contact order.
template <class T, size_t K, class F>
py::array per_sub(const Model& m, F&& value) {
  size_t n = 0;
  for (const Contact3& c : m.contacts3) n += c.subs.size();
  std::vector<std::pair<uint32_t, const SubContact*>> all;
  all.reserve(n);
  for (size_t i = 0; i < m.contacts3.size(); ++i)
    for (const SubContact& s : m.contacts3[i].subs) all.emplace_back(i, &s);
  return copy<T>(n, K, [&](size_t j, T* row) { value(all[j].first, *all[j].second, row); });
}

const Spec kSubContacts[] = {
    {"contact", "row of the contact in Model.contacts (n,) (copy)",
     [](const Model& m, py::handle) {
       return per_sub<uint32_t, 0>(m, [](uint32_t i, const SubContact&, uint32_t* r) { *r = i; });
     }},
    {"point", "point on the common plane (n, 3), m (copy)",
     [](const Model& m, py::handle) {
       return per_sub<double, 3>(m, [&m](uint32_t i, const SubContact& s, double* r) {
         const Vec3 x = world_point(m.blocks3, m.contacts3[i], s);
         for (int k = 0; k < 3; ++k) r[k] = x[k];
       });
     }},
    {"area", "area (n,), m^2 (copy)",
     [](const Model& m, py::handle) {
       return per_sub<double, 0>(m, [](uint32_t, const SubContact& s, double* r) { *r = s.area; });
     }},
    {"normal_force", "normal force (n,), N, compression positive (copy)",
     [](const Model& m, py::handle) {
       return per_sub<double, 0>(m, [](uint32_t, const SubContact& s, double* r) { *r = s.fn; });
     }},
    {"shear_force", "shear force on the first block (n, 3), N (copy)",
     [](const Model& m, py::handle) {
       return per_sub<double, 3>(m, [&](uint32_t i, const SubContact& s, double* r) {
         const Vec3 f = shear_force(m.contacts3[i], s);
         for (int k = 0; k < 3; ++k) r[k] = f[k];
       });
     }},
    {"gap", "gap (n,), m (copy)",
     [](const Model& m, py::handle) {
       return per_sub<double, 0>(m, [](uint32_t, const SubContact& s, double* r) { *r = s.gap; });
     }},
    {"state", "state bits (n,), as Model.contacts.state (copy)",
     [](const Model& m, py::handle) {
       return per_sub<uint8_t, 0>(m,
                                  [](uint32_t, const SubContact& s, uint8_t* r) { *r = s.flags; });
     }},
};

// Zones and nodes of the model's dimension.
template <class F>
py::array continuum(const Model& m, F&& f) {
  return m.dim == 3 ? f(m.continuum3) : f(m.continuum);
}

const Spec kZones[] = {
    {"stress",
     "stress (n, 6), Pa, tension positive, columns xx yy xy zz yz xz (view; 2D: zz is the "
     "plane-strain stress, yz = xz = 0)",
     [](const Model& m, py::handle o) {
       return continuum(m, [&](const auto& c) {
         static_assert(sizeof(ZoneStress) == 6 * sizeof(double));
         return view(c.stress.empty() ? nullptr : &c.stress[0].xx, c.stress.size(), 6,
                     sizeof(ZoneStress), o);
       });
     }},
    {"nodes", "corner nodes of each zone (n, dim + 1), rows of Model.nodes (view)",
     [](const Model& m, py::handle o) {
       return continuum(m, [&](const auto& c) {
         using Zone = typename std::decay_t<decltype(c)>::Zone;
         return view(c.zones.empty() ? nullptr : c.zones[0].data(), c.zones.size(),
                     std::tuple_size_v<Zone>, sizeof(Zone), o);
       });
     }},
    {"state", "plastic state bits (n,): shear now 1, tension now 2, shear past 4, tension past 8",
     [](const Model& m, py::handle o) {
       return continuum(m, [&](const auto& c) { return whole(c.state, o); });
     }},
    {"material", "material (n,): 0 null (excavated), k + 1 the model's material k (view)",
     [](const Model& m, py::handle o) {
       return continuum(m, [&](const auto& c) { return whole(c.material, o); });
     }},
    {"centroid", "centroid of the corner nodes (n, dim), m (copy)",
     [](const Model& m, py::handle) {
       return continuum(m, [&](const auto& c) {
         const size_t d = static_cast<size_t>(m.dim);
         return copy<double>(c.zone_count(), d, [&](size_t z, double* row) {
           for (size_t k = 0; k < d; ++k) {
             row[k] = 0.0;
             for (uint32_t n : c.zones[z]) row[k] += c.pos[n][static_cast<int>(k)] / double(d + 1);
           }
         });
       });
     }},
};

const Spec kNodes[] = {
    {"pos", "positions (n, dim), m (view)",
     [](const Model& m, py::handle o) {
       return continuum(m, [&](const auto& c) { return whole(c.pos, o); });
     }},
    {"disp", "displacements (n, dim), m (copy)",
     [](const Model& m, py::handle) {
       return continuum(m, [&](const auto& c) {
         const size_t d = static_cast<size_t>(m.dim);
         return copy<double>(c.node_count(), d, [&](size_t n, double* row) {
           for (size_t k = 0; k < d; ++k) {
             const int j = static_cast<int>(k);
             row[k] = c.pos[n][j] - c.pos0[n][j];
           }
         });
       });
     }},
    {"vel", "velocities (n, dim), m/s (view)",
     [](const Model& m, py::handle o) {
       return continuum(m, [&](const auto& c) { return whole(c.vel, o); });
     }},
    {"applied", "applied loads (n, dim), N: tractions and Model.set_node_force (view)",
     [](const Model& m, py::handle o) {
       return continuum(m, [&](const auto& c) { return whole(c.applied, o); });
     }},
    {"mass", "lumped masses (n,), kg (view)",
     [](const Model& m, py::handle o) {
       return continuum(m, [&](const auto& c) { return whole(c.mass, o); });
     }},
};

size_t block_rows(const Model& m) {
  return m.block_count();
}
size_t contact_rows(const Model& m) {
  return m.dim == 3 ? m.contacts3.size() : m.contacts.size();
}
size_t sub_rows(const Model& m) {
  size_t n = 0;
  for (const Contact3& c : m.contacts3) n += c.subs.size();
  return n;
}
size_t zone_rows(const Model& m) {
  return m.dim == 3 ? m.continuum3.zone_count() : m.continuum.zone_count();
}
size_t node_rows(const Model& m) {
  return m.dim == 3 ? m.continuum3.node_count() : m.continuum.node_count();
}

// A group's Python class: one read-only property per array, its length, and `names`.
template <class G, size_t N>
void bind_group(py::module_& mod, const char* cls, const char* doc, const Spec (&specs)[N],
                size_t (*rows)(const Model&), bool only3 = false) {
  py::class_<G> c(mod, cls, doc);
  for (const Spec& s : specs)
    c.def_property_readonly(
        s.name,
        [s, only3](const G& g) {
          if (only3 && g.model().dim != 3)
            throw py::value_error(
                "sub-contacts belong to 3D models; a 2D model's contacts are in "
                "Model.contacts");
          return s.make(g.model(), g.owner);
        },
        s.doc);
  c.def("__len__", [rows](const G& g) { return rows(g.model()); });
  std::vector<std::string> names;
  for (const Spec& s : specs) names.emplace_back(s.name);
  c.def_property_readonly_static("names", [names](py::object) { return names; });
}

}  // namespace

void bind_arrays(py::module_& m) {
  bind_group<BlockGroup>(m, "Blocks", "Block arrays, one row per block", kBlocks, block_rows);
  bind_group<ContactGroup>(m, "Contacts", "Contact arrays, one row per contact", kContacts,
                           contact_rows);
  bind_group<SubContactGroup>(m, "SubContacts", "3D sub-contacts, one row each, in contact order",
                              kSubContacts, sub_rows, true);
  bind_group<ZoneGroup>(m, "Zones", "Zone arrays, one row per zone", kZones, zone_rows);
  bind_group<NodeGroup>(m, "Nodes", "Node arrays of the zoned blocks, one row per node", kNodes,
                        node_rows);

  // Histories: the samples as one (rows, columns) view, and each series by its label.
  py::class_<HistoryGroup>(m, "Histories", "Histories sampled during the run")
      .def_property_readonly("labels",
                             [](const HistoryGroup& g) {
                               std::vector<std::string> out;
                               for (const auto& s : g.model().histories.series)
                                 out.push_back(s.label);
                               return out;
                             })
      .def_property_readonly(
          "cycle", [](const HistoryGroup& g) { return whole(g.model().histories.cycles, g.owner); },
          "cycle of each sample (view)")
      .def_property_readonly(
          "values",
          [](const HistoryGroup& g) {
            const Histories& h = g.model().histories;
            // No histories: (rows, 0), still two-dimensional.
            if (h.columns() == 0)
              return py::array(py::dtype::of<double>(),
                               std::vector<py::ssize_t>{static_cast<py::ssize_t>(h.rows()), 0});
            return view(h.values.empty() ? nullptr : h.values.data(), h.rows(), h.columns(),
                        h.columns() * sizeof(double), g.owner);
          },
          "samples (rows, columns), a column per label (view)")
      .def("__len__", [](const HistoryGroup& g) { return g.model().histories.columns(); })
      .def("__contains__",
           [](const HistoryGroup& g, const std::string& label) {
             return g.model().histories.find(label) >= 0;
           })
      .def(
          "__getitem__",
          [](const HistoryGroup& g, const std::string& label) {
            const Histories& h = g.model().histories;
            const int col = h.find(label);
            if (col < 0) {
              std::vector<std::string> labels;
              for (const auto& s : h.series) labels.push_back(s.label);
              throw py::key_error("no history '" + label + "'" + suggest(label, labels));
            }
            return view(h.values.empty() ? nullptr : h.values.data() + col, h.rows(), 0,
                        h.columns() * sizeof(double), g.owner);
          },
          "one series by its label (view)");
}

}  // namespace tessera::python
