// Contacts between rounded-corner blocks (chapter 5.2.2), stored as struct-of-arrays.
//
// Design. A contact is one convex corner of block `a` (the owner) facing block `b`. The feature
// of `b` it faces is either the straight part of an edge (corner-to-edge: normal = the edge's
// outward normal) or the arc of a rounded corner (corner-to-corner: normal along the line of the
// two arc centres). Each contact keeps its history (shear stress, slip, bond, dilation) while the
// feature it faces may change from cycle to cycle as the corner slides along `b`.
//
// Identity is (a, corner, b); contacts are sorted by unordered block pair and then by identity,
// so that the contacts of one interface lie together. Each joint line of an interface (contacts
// whose normals agree) shares its length between its contacts by the chapter's rule L = RQ1/2 +
// RQ2/2, with the neighbouring contacts along the interface as Q1 and Q2 (all contacts within the
// tolerance count, touching or not, so that L does not jump when one corner lifts) where the joint
// runs between them (between a concave block's contacts it may not: across a tunnel, say;
// contact2d/joint_lines.hpp); a lone contact, and never less than this, takes the chord of its
// rounded arc across the opposite edge or arc (cases 2 and 3 of 5.2.2).
//
// A corner sitting in the notch of a concave block touches two of its faces: it then has two
// contacts (slots 0 and 1), each held to its own face until the next detection pass.
//
// A corner-to-corner touch is kept once: only the owner with the lower block index may face a
// corner; the higher one faces edges only. Contacts are found within a tolerance before the
// blocks touch, created and deleted only in detection passes, which run when some block has
// moved half the tolerance since the last pass (a Verlet list), so a touch can never be missed.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "tessera/core/geometry.hpp"
#include "tessera/core/joint_law.hpp"

namespace tessera {

enum ContactKind : uint8_t { kCornerEdge = 0, kCornerCorner = 1, kLost = 2 };
struct Contacts {
  // Identity: global vertex `corner` of block `a` against block `b`; `slot` 1 for the second face
  // of a notch the corner sits in.
  std::vector<uint32_t> a, b, corner;
  std::vector<uint8_t> slot;
  // The feature of b faced: kind, and global vertex index (edge from that vertex to the next).
  std::vector<uint8_t> kind;
  std::vector<uint32_t> feature;
  std::vector<uint8_t> flags;
  std::vector<uint32_t> joint;  // index into the model's joint property table
  std::vector<int> tag;         // joint tag of the face met when the contact was made
  // Geometry of the current cycle: unit normal (from b towards a), contact point, gap (negative
  // when overlapping), and the share of interface length. Between a cycle's geometry stage and
  // its interfaces `length` holds the chord of the rounded arc instead (0 for a lost contact):
  // the length's lower bound, which the interfaces read just before they write the share over
  // it (a chord of its own would be 8 bytes a contact).
  std::vector<Vec2> normal, point;
  std::vector<double> gap, length;
  // Joint law state: normal and shear force on a (compression positive), the normal
  // displacement of the last cycle, dilation and total shear displacement.
  std::vector<double> fn, fs, un_prev, dilation, shear_disp;
  // Held only when used (16 bytes a contact otherwise zero): empty, or one per contact.
  // `closure`, the normal displacement the joint had already taken under the in-situ stress
  // (sigma_n / kn), is added to the overlap like dilation, so that a joint drawn shut starts
  // loaded (`insitu`); `plastic`, the plastic shear displacement travelled (the history of
  // law=cy, barton-bandis and plug-in laws).
  std::vector<double> closure, plastic;
  // The dashpot's normal and shear force this cycle, held only while some joint is damped: the
  // force on the blocks is the spring's (fn, fs) plus these.
  std::vector<double> damp_fn, damp_fs;
  // Interface ranges: contacts of pair p are [pair_begin[p], pair_begin[p+1]).
  std::vector<uint32_t> pair_begin{0};
  // Per interface, this cycle: the force of its contacts on its first contact's block a, their
  // moment about that block's centroid, and the sum of their |Fn| + |Fs| (dashpots included).
  // The interfaces stage writes them pair by pair; the block sums read them, so that a
  // contact's force is formed once, where the law leaves it, instead of once per block side.
  std::vector<Vec2> pair_force;
  std::vector<double> pair_moment, pair_load;

  size_t size() const { return a.size(); }
  size_t pair_count() const { return pair_begin.size() - 1; }
  double closure_at(size_t i) const { return closure.empty() ? 0.0 : closure[i]; }
  double plastic_at(size_t i) const { return plastic.empty() ? 0.0 : plastic[i]; }
  // Normal and shear force on block a this cycle, dashpot included (compression positive).
  double total_fn(size_t i) const { return damp_fn.empty() ? fn[i] : fn[i] + damp_fn[i]; }
  double total_fs(size_t i) const { return damp_fs.empty() ? fs[i] : fs[i] + damp_fs[i]; }
  // -1 when `flip`, else +1, as arithmetic: which side of a pair a contact or block is on
  // varies unpredictably, and a branch on it is mispredicted.
  static double side_sign(bool flip) { return 1.0 - 2.0 * static_cast<double>(flip); }
  // Force on block a (block b takes the opposite) from its normal and shear force and the unit
  // normal: formed from the law's forces rather than kept (24 bytes a contact).
  static Vec2 force_of(double total_fn, double total_fs, const Vec2& n) {
    return total_fn * n + total_fs * perp(n);
  }
  Vec2 force(size_t i) const { return force_of(total_fn(i), total_fs(i), normal[i]); }
  // Gives an optional array (closure, plastic, damp_fn, damp_fs) one zero per contact if it has
  // none.
  void hold(std::vector<double>& optional) {
    if (optional.empty()) optional.assign(size(), 0.0);
  }
  void clear();
  // Applies f to every per-contact array always held (not pair_begin or the optional ones) of
  // one or more stores at once: f(x.a, y.a), f(x.b, y.b), ...
  template <class F, class... Cs>
  static void each_array(F&& f, Cs&... c) {
    each_carried(f, c...);
    f(c.length...);
  }
  // The same less `length`, which every cycle computes afresh before it reads it (the geometry
  // stage, then the interfaces): a detection pass drops it while it runs and gives it back as
  // zeros, and carries these.
  template <class F, class... Cs>
  static void each_carried(F&& f, Cs&... c) {
    f(c.a...), f(c.b...), f(c.corner...), f(c.slot...), f(c.kind...), f(c.feature...);
    f(c.flags...), f(c.joint...), f(c.tag...), f(c.normal...), f(c.point...), f(c.gap...);
    f(c.fn...), f(c.fs...), f(c.un_prev...), f(c.dilation...), f(c.shear_disp...);
  }
  // The same for the arrays held only when used.
  template <class F, class... Cs>
  static void each_optional(F&& f, Cs&... c) {
    f(c.closure...), f(c.plastic...), f(c.damp_fn...), f(c.damp_fs...);
  }
  template <class F>
  void for_each_array(F&& f) {
    each_array(f, *this);
  }
  // Appends a contact copied from another store (used when merging a detection pass).
  void push_from(const Contacts& src, size_t i);
};

}  // namespace tessera
