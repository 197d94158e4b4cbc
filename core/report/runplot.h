#pragma once

#include <QCoreApplication>
#include <QImage>
#include <QLocale>

namespace dd {

struct TuningRun;

// Draws a tuning run's channels as the picture a commissioning record shows: one strip per
// channel (its own value axis, id and unit), one time axis (seconds from the trigger) under
// them, the trigger at time 0 as a dashed line. Lines break where the capture has no sample
// (a NaN, or a gap — over three median intervals — at least 1.5 % of the axis wide); a channel with more samples than
// pixels is drawn as each pixel column's minimum and maximum, so a spike is never lost.
// Needs a QGuiApplication (fonts); text in the current translation.
class RunPlot
{
    Q_DECLARE_TR_FUNCTIONS(dd::RunPlot)
public:
    static constexpr int DefaultWidth = 1200;
    static constexpr int StripHeight = 170;
    static QImage render(const TuningRun &run, const QLocale &locale, int width = DefaultWidth);
};

} // namespace dd
