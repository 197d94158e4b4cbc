#pragma once

#include "ui/workspace/drivecontext.h"

#include <QList>

class QWidget;

namespace dd {

class DrivePanel;

// The tabs every drive gets, in order. To add a panel: write a DrivePanel subclass and add
// one line to createDrivePanels() in drivepanels.cpp. A panel that does not apply to a
// family may still be added and show why (disabled actions with their reasons), or be
// left out for that family there.
QList<DrivePanel *> createDrivePanels(const DriveContext &context, QWidget *parent);

} // namespace dd
