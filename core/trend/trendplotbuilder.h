#pragma once

#include "core/trend/samplebuffer.h"

#include <QList>
#include <QPointF>

namespace dd {

class DecimationCache;

// Turns one channel's buffer into the points a chart series draws for a time window:
// min/max-decimated to the plot width (Decimator), plus the nearest sample outside each
// edge so the line reaches the border. x is seconds since originUs, y is
// value × scale + offset. At most 2 × widthPx points: the window touches at most
// widthPx - 1 buckets (≤ 2 points each) and the two edge points make up the rest (below
// 2 px: one bucket, no edge points).
// Buckets are anchored to absolute time (Decimator::minMaxAligned, bucketUs()), so as a
// live window slides a bucket keeps its points; with a DecimationCache (one per channel)
// only the buckets at the window's edges are computed again. With or without the cache
// the points are the same.
// Gaps: where the buffer holds a gap marker (a NaN sample, see SampleBuffer) between two
// consecutive points, a point with y = NaN is put between them: the view breaks the line
// there instead of drawing a ramp across the gap. Break points are extra to the bound
// above (one per gap in the window).
class TrendPlotBuilder
{
public:
    struct Result
    {
        QList<QPointF> points; // y = NaN: a break (a gap in the recording)
        // Range of y over the points inside the window (edge points excluded);
        // yMin > yMax when the window holds no sample.
        double yMin = 0.0;
        double yMax = -1.0;
        bool hasData() const { return yMin <= yMax; }
    };

    static Result build(const SampleBuffer &buffer, qint64 fromUs, qint64 toUs, int widthPx, qint64 originUs,
                        double scale = 1.0, double offset = 0.0, DecimationCache *cache = nullptr);
    // The bucket width for a window and plot width: the window [fromUs, toUs] touches at
    // most widthPx - 1 buckets of this width (at least 1 µs). widthPx >= 3.
    static qint64 bucketUs(qint64 fromUs, qint64 toUs, int widthPx);
};

} // namespace dd
