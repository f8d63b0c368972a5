// Drawing shapes in the view: the points clicked so far, snapping, and the script command the
// finished shape becomes (every edit in the window is a command, so it can be saved, undone
// and rerun in batch).
#pragma once

#include <string>
#include <vector>

#include "tessera/ui/scene.hpp"

namespace tessera::ui {

// kSelect: a click picks a block, a drag selects the blocks whose centroid is in the box.
enum class DrawMode { kNone, kBlock, kCrack, kSelect };

class Drawing {
 public:
  void start(DrawMode mode) { mode_ = mode, points_.clear(); }
  void cancel() { points_.clear(); }
  DrawMode mode() const { return mode_; }
  const std::vector<Vec2>& points() const { return points_; }
  // Adds a point (a repeat of the last one is ignored).
  void add(Vec2 p);
  // Enough points for the shape: three for a block, two for a crack.
  bool complete() const;
  // The command that makes the shape, e.g. "block 0,0 1,0 1,1 group=wall material=stone";
  // empty group or material are left out.
  std::string command(const std::string& group, const std::string& material) const;

  // The point to use for a click at p: the nearest block vertex of the scene within `reach`
  // (model units), else the nearest node of a grid of spacing `grid` (0: no grid), else p.
  static Vec2 snap(Vec2 p, const Scene& scene, double grid, double reach);

 private:
  DrawMode mode_ = DrawMode::kNone;
  std::vector<Vec2> points_;
};

}  // namespace tessera::ui
