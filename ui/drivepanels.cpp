#include "drivepanels.h"

#include "overviewpanel.h"
#include "trendpanel.h"

namespace dd {

QList<DrivePanel *> createDrivePanels(const DriveContext &context, QWidget *parent)
{
    QList<DrivePanel *> panels;
    panels << new OverviewPanel(context, parent);
    panels << new TrendPanel(context, parent);
    // Further panels (parameters, backup/restore, EE, motion, alarms) go here.
    return panels;
}

} // namespace dd
