#pragma once

#include <QByteArray>
#include <QString>

namespace dd {

// One CSV field as UTF-8: unchanged unless it holds a comma, a quote or a line break, then
// quoted with every quote doubled (RFC 4180). Shared by every CSV DriveDesk writes (trends,
// traffic logs, alarm histories), so that all of them quote alike.
QByteArray csvField(const QString &field);

} // namespace dd
