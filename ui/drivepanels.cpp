#include "drivepanels.h"

#include "alarmspanel.h"
#include "motionpanel.h"
#include "overviewpanel.h"
#include "trendpanel.h"

namespace dd {

QList<DrivePanel *> createDrivePanels(const DriveContext &context, QWidget *parent)
{
    QList<DrivePanel *> panels;
    panels << new OverviewPanel(context, parent);
    panels << new TrendPanel(context, parent);
    panels << new MotionPanel(context, parent);
    panels << new AlarmsPanel(context, parent);
    // Further panels (parameters, backup/restore, EE) go here.
    return panels;
}

} // namespace dd
