#include "core/link/cansettings.h"

namespace dd {

bool CanSettings::parse(const QString &text, CanSettings *out)
{
    const qsizetype colon = text.indexOf(QLatin1Char(':'));
    if (colon <= 0 || colon == text.size() - 1)
        return false;
    out->plugin = text.left(colon).trimmed();
    out->interface = text.mid(colon + 1).trimmed();
    return !out->plugin.isEmpty() && !out->interface.isEmpty();
}

} // namespace dd
