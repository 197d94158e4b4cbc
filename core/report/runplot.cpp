#include "core/report/runplot.h"

#include "core/drive/drivetypes.h"
#include "core/report/recordfont.h"
#include "core/trend/trendaxisscale.h"
#include "core/tuning/tuningrun.h"

#include <QPainter>
#include <QPainterPath>
#include <climits>
#include <cmath>
#include <functional>

namespace dd {

namespace {

constexpr int LeftMargin = 100;
constexpr int RightMargin = 18;
constexpr int TopMargin = 10;
constexpr int StripGap = 12;
constexpr int TimeAxisHeight = 48;
constexpr int FontPx = 15;

const QColor LineColors[] = {QColor(0x1f, 0x4e, 0xb4), QColor(0xc0, 0x3a, 0x2b), QColor(0x1b, 0x7f, 0x3b),
                             QColor(0x8e, 0x44, 0xad), QColor(0xd3, 0x7a, 0x00), QColor(0x16, 0x8a, 0x8a)};

QString tickText(double v, double step)
{
    if (std::fabs(v) < step * 1e-6)
        v = 0.0;
    const int decimals = step >= 1.0 ? 0 : int(std::ceil(-std::log10(step) - 1e-9));
    return QString::number(v, 'f', qBound(0, decimals, 6));
}

// The lines of one channel in pixel coordinates: broken at NaN samples and at gaps (an
// interval over `gapSeconds`); where several samples fall into one pixel column, the
// column's extremes in the order they came.
QList<QPolygonF> channelLines(const QVector<double> &time, const QVector<double> &values,
                              const std::function<double(double)> &xOf, const std::function<double(double)> &yOf,
                              double gapSeconds)
{
    QList<QPolygonF> lines;
    QPolygonF current;
    int column = INT_MIN;
    double first = 0, minV = 0, maxV = 0;
    int minAt = 0, maxAt = 0, count = 0;
    auto flushColumn = [&] {
        if (count == 0)
            return;
        const double x = column;
        current << QPointF(x, yOf(first));
        if (count > 1) {
            if (minAt <= maxAt)
                current << QPointF(x, yOf(minV)) << QPointF(x, yOf(maxV));
            else
                current << QPointF(x, yOf(maxV)) << QPointF(x, yOf(minV));
        }
        count = 0;
    };
    auto breakLine = [&] {
        flushColumn();
        if (current.size() > 1)
            lines << current;
        else if (current.size() == 1) // a lone sample: a dot
            lines << QPolygonF{current.first(), current.first() + QPointF(0.5, 0)};
        current.clear();
    };
    double previousTime = NAN;
    for (int i = 0; i < time.size(); ++i) {
        const double v = values.at(i);
        if (!std::isfinite(v)) {
            breakLine();
            previousTime = NAN;
            continue;
        }
        if (std::isfinite(previousTime) && time.at(i) - previousTime > gapSeconds)
            breakLine();
        previousTime = time.at(i);
        const int x = int(std::lround(xOf(time.at(i))));
        if (x != column) {
            flushColumn();
            column = x;
        }
        if (count == 0) {
            first = minV = maxV = v;
            minAt = maxAt = i;
        } else {
            if (v < minV) {
                minV = v;
                minAt = i;
            }
            if (v > maxV) {
                maxV = v;
                maxAt = i;
            }
        }
        ++count;
    }
    breakLine();
    return lines;
}

} // namespace

QImage RunPlot::render(const TuningRun &run, const QLocale &locale, int width)
{
    const CaptureData &c = run.capture;
    const int strips = qMax(1, int(c.channels.size()));
    const int height = TopMargin + strips * StripHeight + (strips - 1) * StripGap + TimeAxisHeight;
    QImage image(width, height, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    QFont font = RecordFont::font(locale, 9);
    font.setPixelSize(FontPx);
    p.setFont(font);
    const QFontMetrics fm(font);

    const double t0 = c.time.isEmpty() ? 0.0 : c.time.first();
    double t1 = c.time.isEmpty() ? 1.0 : c.time.last();
    if (t1 <= t0)
        t1 = t0 + 1e-3;
    const int plotLeft = LeftMargin, plotRight = width - RightMargin;
    const double plotWidth = plotRight - plotLeft;
    auto xOf = [&](double t) { return plotLeft + (t - t0) / (t1 - t0) * plotWidth; };
    // A gap (CaptureGap's: over three median intervals) breaks the line where the plot can show
    // it: wider than MinGapPx (1.5 % of the axis); narrower ones would only make the line look
    // dashed (the record states how many gaps there are and the longest).
    constexpr double MinGapPx = 16.0;
    const double gapSeconds = c.interval.median > 0
        ? std::max(3.0 * c.interval.median, MinGapPx / plotWidth * (t1 - t0))
        : INFINITY;
    const double timeStep = TrendAxisScale::niceStep((t1 - t0) / 8.0);
    const int plotBottom = height - TimeAxisHeight;

    // Time grid across every strip, the trigger at 0.
    const QPen gridPen(QColor(0xdd, 0xdd, 0xdd), 1);
    const QPen axisPen(QColor(0x66, 0x66, 0x66), 1);
    const QPen textPen(QColor(0x22, 0x22, 0x22));
    for (double t = std::ceil(t0 / timeStep) * timeStep; t <= t1 + timeStep * 1e-9; t += timeStep) {
        const double x = xOf(t);
        p.setPen(gridPen);
        p.drawLine(QPointF(x, TopMargin), QPointF(x, plotBottom));
        p.setPen(textPen);
        const QString label = tickText(t, timeStep);
        p.drawText(QRectF(x - 60, plotBottom + 4, 120, fm.height()), Qt::AlignHCenter | Qt::AlignTop, label);
    }
    p.setPen(textPen);
    p.drawText(QRectF(plotLeft, plotBottom + 6 + fm.height(), plotWidth, fm.height()), Qt::AlignHCenter | Qt::AlignTop,
               tr("time from the trigger (s)"));

    for (int s = 0; s < c.channels.size(); ++s) {
        const QRectF strip(plotLeft, TopMargin + s * (StripHeight + StripGap), plotWidth, StripHeight);
        const QVector<double> &values = c.columns.at(s);
        double lo = INFINITY, hi = -INFINITY;
        for (double v : values)
            if (std::isfinite(v)) {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
        p.setPen(axisPen);
        p.drawRect(strip);
        const QString unit = channelUnitText(run.units.value(s)); // run files keep the untranslated unit
        const QString title = unit.isEmpty() ? c.channels.at(s) : QStringLiteral("%1 (%2)").arg(c.channels.at(s), unit);
        if (lo > hi) {
            p.setPen(textPen);
            p.drawText(strip, Qt::AlignCenter, tr("%1: no sample").arg(c.channels.at(s)));
            continue;
        }
        const auto range = TrendAxisScale::fitValueRange(lo, hi, 0.0, -1.0);
        auto yOf = [&](double v) {
            return strip.bottom() - (v - range.first) / (range.second - range.first) * strip.height();
        };
        const double step = TrendAxisScale::niceStep((range.second - range.first) / 4.0);
        for (double v = std::ceil(range.first / step) * step; v <= range.second; v += step) {
            const double y = yOf(v);
            if (y < strip.top() + fm.height() / 2.0 || y > strip.bottom() - fm.height() / 2.0)
                continue; // its label would run into the next strip's
            p.setPen(gridPen);
            p.drawLine(QPointF(strip.left() + 1, y), QPointF(strip.right() - 1, y));
            p.setPen(textPen);
            p.drawText(QRectF(0, y - fm.height() / 2.0, plotLeft - 6, fm.height()), Qt::AlignRight | Qt::AlignVCenter,
                       tickText(v, step));
        }
        p.save();
        p.setClipRect(strip.adjusted(1, 1, -1, -1));
        p.setPen(QPen(LineColors[s % std::size(LineColors)], 2.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        for (const QPolygonF &line : channelLines(c.time, values, xOf, yOf, gapSeconds))
            p.drawPolyline(line);
        p.restore();
        // The channel's name over its strip, on white so that no line runs through it.
        const QRect titleRect = fm.boundingRect(title).adjusted(-4, -2, 4, 2);
        const QRectF titleBox(strip.left() + 6, strip.top() + 5, titleRect.width(), titleRect.height());
        p.fillRect(titleBox, Qt::white);
        p.setPen(QPen(LineColors[s % std::size(LineColors)]));
        p.drawText(titleBox, Qt::AlignCenter, title);
    }

    if (0.0 >= t0 && 0.0 <= t1 && !c.time.isEmpty()) {
        const double x = xOf(0.0);
        p.setPen(QPen(QColor(0x55, 0x55, 0x55), 1.5, Qt::DashLine));
        p.drawLine(QPointF(x, TopMargin), QPointF(x, plotBottom));
    }
    p.end();
    return image;
}

} // namespace dd
