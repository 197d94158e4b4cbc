#include "tests/fuzz/fuzzsupport.h"

#include "core/common/coreresources.h"
#include "core/protocol/modbus/crc16.h"

#include <QString>
#include <QtGlobal>

#include <mutex>

namespace dd::fuzz {

namespace {
void quietHandler(QtMsgType type, const QMessageLogContext &, const QString &message)
{
    if (type == QtFatalMsg || type == QtCriticalMsg)
        std::fprintf(stderr, "%s\n", qPrintable(message)); // Qt aborts after a fatal message
}
} // namespace

QByteArray withRepairedCrc(const QByteArray &bytes)
{
    if (bytes.size() < 2)
        return bytes;
    return withCrc16(bytes.chopped(2));
}

QByteArray segmentsWithCrc(FuzzInput &in)
{
    QByteArray out;
    while (in.remaining() > 0) {
        const quint8 h = in.byte();
        const QByteArray segment = in.take(h & 0x7F);
        out += (h & 0x80) ? withCrc16(segment) : segment;
    }
    return out;
}

void initialise()
{
    static std::once_flag once;
    std::call_once(once, [] {
        qInstallMessageHandler(quietHandler);
        dd::ensureCoreResources();
    });
}

} // namespace dd::fuzz
