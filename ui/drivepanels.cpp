#include "drivepanels.h"

#include "backuppanel.h"
#include "eepanel.h"
#include "overviewpanel.h"
#include "parameterspanel.h"
#include "trendpanel.h"

namespace dd {

QList<DrivePanel *> createDrivePanels(const DriveContext &context, QWidget *parent)
{
    QList<DrivePanel *> panels;
    panels << new OverviewPanel(context, parent);
    panels << new ParametersPanel(context, parent);
    panels << new TrendPanel(context, parent);
    panels << new BackupPanel(context, parent);
    // EEPROM operations: servo-modbus (the capabilities may not be known yet when the tabs
    // are made; a drive without them shows why).
    if (context.family == Family::ServoModbus || context.can(Capability::EeOperations))
        panels << new EePanel(context, parent);
    // Further panels (motion, alarms) go here.
    return panels;
}

} // namespace dd
