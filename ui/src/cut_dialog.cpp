// View > Cut plane: the plane a 3D view is cut by, as view options (the window and figures
// exported from it clip alike).
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QStatusBar>

#include "tessera/ui/main_window.hpp"

namespace tessera::ui {

void MainWindow::cutDialog() {
  if (!shown_ || !shown_->three) {
    statusBar()->showMessage("A cut plane is for 3D models", 5000);
    return;
  }
  QDialog d(this);
  d.setWindowTitle("Cut plane");
  auto* form = new QFormLayout(&d);
  form->addRow(
      new QLabel("What lies above the plane is not drawn (for a vertical plane: the "
                 "side its dip direction faces)."));
  // Unless a cut is on: a vertical plane facing the viewer through the blocks' mean centroid.
  Vec3 centre = Vec3::Zero();
  for (const auto& b : shown_->blocks) centre += Vec3(b.x, b.y, b.z);
  if (!shown_->blocks.empty()) centre /= static_cast<double>(shown_->blocks.size());
  const ViewOptions& o = options_;
  const auto field = [&](const char* name, const QString& label, double lo, double hi, double value,
                         const QString& unit) {
    auto* box = new QDoubleSpinBox(&d);
    box->setObjectName(name);
    box->setRange(lo, hi);
    box->setDecimals(3);
    box->setValue(value);
    box->setSuffix(unit);
    form->addRow(label, box);
    return box;
  };
  QDoubleSpinBox* dip = field("dip", "Dip", 0, 90, o.cut ? o.cut_dip : 90, " °");
  QDoubleSpinBox* dir = field("dip_direction", "Dip direction", 0, 360,
                              o.cut ? o.cut_dip_direction : o.azimuth, " °");
  const Vec3 at = o.cut ? Vec3(o.cut_point) : centre;
  QDoubleSpinBox* x = field("x", "Through x", -1e9, 1e9, at.x(), " m");
  QDoubleSpinBox* y = field("y", "y", -1e9, 1e9, at.y(), " m");
  QDoubleSpinBox* z = field("z", "z", -1e9, 1e9, at.z(), " m");
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &d);
  buttons->button(QDialogButtonBox::Ok)->setText("Cut");
  connect(buttons, &QDialogButtonBox::accepted, &d, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &d, &QDialog::reject);
  form->addRow(buttons);
  if (d.exec() != QDialog::Accepted) return;
  options_.cut = true;
  options_.cut_dip = dip->value(), options_.cut_dip_direction = dir->value();
  options_.cut_point = Vec3(x->value(), y->value(), z->value());
  redraw();
}

}  // namespace tessera::ui
