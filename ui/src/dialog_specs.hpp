// The fields of each Model menu dialog (model_dialogs.cpp builds the dialogs from them).
#pragma once

#include <QString>
#include <vector>

#include "tessera/ui/command_dialog.hpp"

namespace tessera::ui {

struct DialogSpec {
  QString title, head;
  std::vector<CommandField> fields;
  bool on_selection = false;  // the selection's keywords are appended
};

// The dialog of a Model menu entry in a 2D or 3D model (no title: none in that dimension).
DialogSpec dialog_spec(const QString& name, bool three);

}  // namespace tessera::ui
