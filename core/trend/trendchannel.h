#pragma once

#include "core/drive/drivetypes.h"

#include <QList>
#include <QMetaType>
#include <QString>

namespace dd {

// One recorded quantity: a stable id (the drive's channel id, e.g. "speed"), a translated
// display name and a unit ("r/min", "A", "" for none). The id and unit name the CSV
// columns; the display name labels the plot.
struct TrendChannel
{
    QString id;
    QString name;
    QString unit;
    int decimals = 0; // digits after the point in readouts

    // "Speed [r/min]" or just "Speed" when there is no unit (the id when the name is empty).
    QString label() const
    {
        const QString n = name.isEmpty() ? id : name;
        return unit.isEmpty() ? n : n + QStringLiteral(" [") + unit + QLatin1Char(']');
    }

    static TrendChannel fromInfo(const ChannelInfo &info)
    {
        return TrendChannel{info.id, info.name, info.unit, info.decimals};
    }
    static QList<TrendChannel> fromInfos(const QList<ChannelInfo> &infos)
    {
        QList<TrendChannel> out;
        out.reserve(infos.size());
        for (const ChannelInfo &i : infos)
            out.append(fromInfo(i));
        return out;
    }

    friend bool operator==(const TrendChannel &a, const TrendChannel &b)
    {
        return a.id == b.id && a.name == b.name && a.unit == b.unit && a.decimals == b.decimals;
    }
    friend bool operator!=(const TrendChannel &a, const TrendChannel &b) { return !(a == b); }
};

} // namespace dd

Q_DECLARE_METATYPE(dd::TrendChannel)
