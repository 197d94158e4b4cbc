#pragma once

#include "core/trend/trendchannel.h"
#include "core/trend/trendsample.h"

#include <QList>

namespace dd {

// A copy of part of a recording: the channels (in column order) and, for each, its
// samples in the window (series[i] belongs to channels[i]). originUs is the recording's
// time zero (CSV time_s and the plot's time axis count from it).
struct TrendSnapshot
{
    QList<TrendChannel> channels;
    QList<QList<TrendSample>> series;
    qint64 originUs = 0;
    qint64 fromUs = 0; // the window asked for
    qint64 toUs = 0;

    qsizetype sampleCount() const
    {
        qsizetype n = 0;
        for (const auto &s : series)
            n += s.size();
        return n;
    }
};

} // namespace dd
