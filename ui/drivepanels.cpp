#include "drivepanels.h"

#include "overviewpanel.h"

namespace dd {

QList<DrivePanel *> createDrivePanels(const DriveContext &context, QWidget *parent)
{
    QList<DrivePanel *> panels;
    panels << new OverviewPanel(context, parent);
    // Further panels (parameters, backup/restore, EE, motion, trend, alarms) go here.
    return panels;
}

} // namespace dd
