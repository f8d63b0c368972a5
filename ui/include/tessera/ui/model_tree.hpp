// The model tree (blocks by group, groups, materials, joint properties, boundary conditions,
// histories, stages) and the property panel that shows the selected item's values.
#pragma once

#include <QTableWidget>
#include <QTreeWidget>
#include <string>
#include <utility>
#include <vector>

#include "tessera/ui/snapshot.hpp"

namespace tessera::ui {

using Properties = std::vector<std::pair<std::string, std::string>>;

class PropertyPanel : public QTableWidget {
  Q_OBJECT
 public:
  explicit PropertyPanel(QWidget* parent = nullptr);
  void show(const QString& heading, const Properties& properties);
  QString heading() const { return heading_; }
  // The value of a property shown now, or empty.
  QString value(const QString& name) const;

 private:
  QString heading_;
};

class ModelTree : public QTreeWidget {
  Q_OBJECT
 public:
  explicit ModelTree(QWidget* parent = nullptr);
  // Refills the tree if the catalogue changed; keeps the selection where it can.
  void update(const Snapshot& s);

 signals:
  void selected(const QString& heading, const Properties& properties);

 private:
  std::string signature_;                              // catalogue the tree was built from
  std::vector<std::pair<QString, Properties>> items_;  // by item data index
};

// What a block or contact of a snapshot shows in the property panel.
Properties block_properties(const Snapshot& s, int block);
Properties contact_properties(const Snapshot& s, int contact);
// A zone's stresses (MPa, tension positive) and plastic state.
Properties zone_properties(const Snapshot& s, int zone);

}  // namespace tessera::ui
