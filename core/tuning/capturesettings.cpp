#include "core/tuning/capturesettings.h"

namespace dd {

QString CaptureSettings::modeId(Mode mode)
{
    switch (mode) {
    case Mode::Single: return QStringLiteral("single");
    case Mode::Normal: return QStringLiteral("normal");
    case Mode::Auto: return QStringLiteral("auto");
    }
    return {};
}

std::optional<CaptureSettings::Mode> CaptureSettings::modeFromId(const QString &id)
{
    for (Mode m : {Mode::Single, Mode::Normal, Mode::Auto})
        if (modeId(m) == id)
            return m;
    return std::nullopt;
}

} // namespace dd
