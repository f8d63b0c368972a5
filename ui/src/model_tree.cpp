// Model tree filling and the property tables of blocks and contacts.
#include "tessera/ui/model_tree.hpp"

#include <QHeaderView>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "tessera/contact2d/blocks.hpp"
#include "tessera/contact2d/contacts.hpp"
#include "tessera/contact3d/blocks3.hpp"
#include "tessera/ui/scene.hpp"

namespace tessera::ui {

namespace {
std::string num(double v, const char* unit = "") {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g%s%s", v, *unit ? " " : "", unit);
  return buf;
}
}  // namespace

PropertyPanel::PropertyPanel(QWidget* parent) : QTableWidget(0, 2, parent) {
  setHorizontalHeaderLabels({"property", "value"});
  horizontalHeader()->setStretchLastSection(true);
  verticalHeader()->hide();
  setEditTriggers(QAbstractItemView::NoEditTriggers);
}

void PropertyPanel::show(const QString& heading, const Properties& properties) {
  heading_ = heading;
  setRowCount(static_cast<int>(properties.size()) + 1);
  setItem(0, 0, new QTableWidgetItem("item"));
  setItem(0, 1, new QTableWidgetItem(heading));
  for (size_t i = 0; i < properties.size(); ++i) {
    const int r = static_cast<int>(i) + 1;
    setItem(r, 0, new QTableWidgetItem(QString::fromStdString(properties[i].first)));
    setItem(r, 1, new QTableWidgetItem(QString::fromStdString(properties[i].second)));
  }
  resizeColumnToContents(0);
}

QString PropertyPanel::value(const QString& name) const {
  for (int r = 0; r < rowCount(); ++r)
    if (item(r, 0) && item(r, 0)->text() == name) return item(r, 1)->text();
  return {};
}

ModelTree::ModelTree(QWidget* parent) : QTreeWidget(parent) {
  setHeaderLabels({"model", ""});
  header()->setStretchLastSection(true);
  connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
    if (!item) return;
    const int i = item->data(0, Qt::UserRole).toInt();
    if (i > 0 && static_cast<size_t>(i) <= items_.size())
      emit selected(items_[static_cast<size_t>(i) - 1].first,
                    items_[static_cast<size_t>(i) - 1].second);
  });
}

void ModelTree::update(const Snapshot& s) {
  // The catalogue's fingerprint: rebuild only when it changed.
  std::string sig = std::to_string(s.blocks.size()) + "|" + std::to_string(s.history_labels.size());
  for (const auto& g : s.groups) sig += g + ",";
  for (const auto* list : {&s.materials, &s.joints, &s.conditions, &s.stages})
    for (const Entry& e : *list) {
      sig += e.name + ";";
      for (const auto& [k, v] : e.properties) sig += k + "=" + v + ";";
    }
  if (sig == signature_) return;
  signature_ = sig;
  const QString current = currentItem() ? currentItem()->text(0) : QString();
  clear();
  items_.clear();
  auto add = [&](QTreeWidgetItem* parent, const QString& name, const QString& note,
                 Properties props) {
    auto* item = new QTreeWidgetItem(parent, {name, note});
    items_.emplace_back(name, std::move(props));
    item->setData(0, Qt::UserRole, static_cast<int>(items_.size()));
    return item;
  };
  auto top = [&](const QString& name, size_t count) {
    auto* item = new QTreeWidgetItem(this, {name, QString::number(count)});
    return item;
  };
  // Blocks, by group.
  auto* blocks = top("Blocks", s.blocks.size());
  std::vector<size_t> per_group(s.groups.size() + 1, 0);
  std::vector<double> area(s.groups.size() + 1, 0);
  for (const auto& b : s.blocks) {
    const size_t g = b.group >= 0 ? static_cast<size_t>(b.group) : s.groups.size();
    ++per_group[g], area[g] += b.area;
  }
  auto* groups = top("Groups", s.groups.size());
  for (size_t g = 0; g < s.groups.size(); ++g) {
    const QString name = QString::fromStdString(s.groups[g]);
    Properties p{{"blocks", std::to_string(per_group[g])},
                 s.three ? std::pair<std::string, std::string>{"volume", num(area[g], "m³")}
                         : std::pair<std::string, std::string>{"area", num(area[g], "m²")}};
    add(blocks, name, QString::number(per_group[g]) + " blocks", p);
    add(groups, name, "", p);
  }
  auto entries = [&](const QString& name, const std::vector<Entry>& list) {
    auto* t = top(name, list.size());
    for (const Entry& e : list) add(t, QString::fromStdString(e.name), "", e.properties);
  };
  entries("Materials", s.materials);
  entries("Joint properties", s.joints);
  entries("Boundary conditions", s.conditions);
  auto* histories = top("Histories", s.history_labels.size());
  for (const auto& h : s.history_labels)
    add(histories, QString::fromStdString(h), "",
        {{"samples", std::to_string(s.history_cycles.size())}});
  entries("Stages", s.stages);
  expandToDepth(0);
  resizeColumnToContents(0);
  if (!current.isEmpty()) {
    const auto found = findItems(current, Qt::MatchExactly | Qt::MatchRecursive);
    if (!found.isEmpty()) setCurrentItem(found.front());
  }
}

Properties block_properties(const Snapshot& s, int block) {
  const SnapshotBlock& b = s.blocks.at(static_cast<size_t>(block));
  const auto group = b.group >= 0 && static_cast<size_t>(b.group) < s.groups.size()
                         ? s.groups[static_cast<size_t>(b.group)]
                         : std::string("-");
  const auto material = b.material >= 0 && static_cast<size_t>(b.material) < s.materials.size()
                            ? s.materials[static_cast<size_t>(b.material)].name
                            : std::string("-");
  std::string fixed;
  if (s.three) {
    // 3D: the body's motion (a piece of a joined block shows its whole body's).
    if (b.fixity & kFix3X) fixed += "x ";
    if (b.fixity & kFix3Y) fixed += "y ";
    if (b.fixity & kFix3Z) fixed += "z ";
    if (b.fixity & kFix3Rot) fixed += "rotation";
    return {{"id", std::to_string(b.id)},
            {"group", group},
            {"material", material},
            {"centroid", num(b.x, "") + ", " + num(b.y, "") + ", " + num(b.z, "m")},
            {"displacement", num(b.x - b.x_ref, "") + ", " + num(b.y - b.y_ref, "") + ", " +
                                 num(b.z - b.z_ref, "m")},
            {"velocity", num(b.vx, "") + ", " + num(b.vy, "") + ", " + num(b.vz, "m/s")},
            {"turned", num(b.theta * 180 / std::numbers::pi, "°")},
            {"angular velocity", num(b.omega, "rad/s")},
            {"volume", num(b.area, "m³")},
            {"mass", num(b.mass, "kg")},
            {"fixed", fixed.empty() ? "free" : fixed}};
  }
  if (b.fixity & kFixX) fixed += "x ";
  if (b.fixity & kFixY) fixed += "y ";
  if (b.fixity & kFixRot) fixed += "rotation";
  return {{"id", std::to_string(b.id)},
          {"group", group},
          {"material", material},
          {"centroid x", num(b.x, "m")},
          {"centroid y", num(b.y, "m")},
          {"x displacement", num(b.x - b.x_ref, "m")},
          {"y displacement", num(b.y - b.y_ref, "m")},
          {"rotation", num(b.theta * 180 / std::numbers::pi, "°")},
          {"x velocity", num(b.vx, "m/s")},
          {"y velocity", num(b.vy, "m/s")},
          {"angular velocity", num(b.omega, "rad/s")},
          {"area", num(b.area, "m²")},
          {"mass", num(b.mass, "kg/m")},
          {"fixed", fixed.empty() ? "free" : fixed}};
}

Properties contact_properties(const Snapshot& s, int contact) {
  const SnapshotContact& c = s.contacts.at(static_cast<size_t>(contact));
  const char* state = !(c.flags & kTouching) ? "open"
                      : c.flags & kSlipping  ? "slipping"
                      : c.flags & kBonded    ? "bonded"
                                             : "elastic";
  if (s.three)
    // A sub-contact: its point, the area it stands for, forces in newtons.
    return {{"blocks", std::to_string(s.blocks[static_cast<size_t>(c.a)].id) + " and " +
                           std::to_string(s.blocks[static_cast<size_t>(c.b)].id)},
            {"joint", c.joint},
            {"state", std::string(state) + (c.flags & kBroken ? " (bond broken)" : "")},
            {"point",
             num(c.point3.x(), "") + ", " + num(c.point3.y(), "") + ", " + num(c.point3.z(), "m")},
            {"normal", num(c.normal3.x(), "") + ", " + num(c.normal3.y(), "") + ", " +
                           num(c.normal3.z(), "")},
            {"area", num(4 * c.length * c.length, "m²")},
            {"gap", num(c.gap, "m")},
            {"normal force", num(c.fn, "N")},
            {"shear force", num(c.fs, "N")},
            {"shear displacement", num(c.shear_disp, "m")}};
  return {{"blocks", std::to_string(s.blocks[static_cast<size_t>(c.a)].id) + " and " +
                         std::to_string(s.blocks[static_cast<size_t>(c.b)].id)},
          {"joint", c.joint},
          {"state", std::string(state) + (c.flags & kBroken ? " (bond broken)" : "")},
          {"x", num(c.point.x(), "m")},
          {"y", num(c.point.y(), "m")},
          {"length", num(c.length, "m")},
          {"gap", num(c.gap, "m")},
          {"normal force", num(c.fn, "N/m")},
          {"shear force", num(c.fs, "N/m")},
          {"shear displacement", num(c.shear_disp, "m")}};
}

Properties zone_properties(const Snapshot& s, int zone) {
  const SnapshotZone& z = s.zones.at(static_cast<size_t>(zone));
  static const char* states[] = {"elastic", "yielding in shear", "yielding in tension",
                                 "yielded before"};
  Properties p{{"zone", std::to_string(z.index + 1)},
               {"block", z.block >= 0 && static_cast<size_t>(z.block) < s.blocks.size()
                             ? std::to_string(s.blocks[static_cast<size_t>(z.block)].id)
                             : std::string("-")}};
  // Stresses as the pictures show them (MPa, tension positive).
  std::vector<ColourBy> shown{ColourBy::kSxx, ColourBy::kSyy, ColourBy::kSxy, ColourBy::kSzz};
  if (s.three) shown = {ColourBy::kSxx, ColourBy::kSyy, ColourBy::kSzz, ColourBy::kSxy};
  for (ColourBy c : shown)
    p.push_back({colour_by_names()[size_t(c)], num(zone_value(z, c), "MPa")});
  if (s.three)
    p.push_back({"syz", num(z.syz * 1e-6, "MPa")}), p.push_back({"sxz", num(z.sxz * 1e-6, "MPa")});
  p.push_back({"sigma1", num(zone_value(z, ColourBy::kSigma1), "MPa")});
  p.push_back({"sigma3", num(zone_value(z, ColourBy::kSigma3), "MPa")});
  p.push_back({"state", states[std::clamp(zone_state_category(z.state), 0, 3)]});
  return p;
}

}  // namespace tessera::ui
