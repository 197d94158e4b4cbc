#include "core/protocol/framedescriber.h"

namespace dd {

QString FrameDescriber::describeSerial(Origin, const QByteArray &)
{
    return unknown();
}

QString FrameDescriber::describeCan(Origin, const CanFrameData &)
{
    return unknown();
}

QString FrameDescriber::unknown()
{
    return QStringLiteral("?");
}

QString FrameDescriber::failed(const QString &reason)
{
    return reason.isEmpty() ? unknown() : QStringLiteral("%1 (%2)").arg(unknown(), reason);
}

QString FrameDescriber::station(int address)
{
    return QStringLiteral("#%1 ").arg(address);
}

} // namespace dd
