#pragma once

#include "core/common/error.h"
#include "core/tuning/capturedata.h"
#include "core/tuning/capturesettings.h"
#include "core/tuning/stepmetrics.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonObject>

namespace dd {

// One tuning parameter as read from the drive when the run was taken.
struct TuningSnapshotEntry
{
    int index = -1;
    QString key;  // "P60", "PA5"
    QString role; // "speed-kp", ... ("" when the dictionary gives none)
    qint64 value = 0;
};

// A run: one capture with what it was taken from and what it measured — the content of a
// .ddrun file (JSON, docs/tuning.md). Loading validates everything and refuses a bad file
// with the reason; saving is atomic.
struct TuningRun
{
    Q_DECLARE_TR_FUNCTIONS(dd::TuningRun)

public:
    static constexpr int FormatVersion = 1;
    static constexpr qint64 MaxFileSize = 64 * 1024 * 1024;
    // The most samples (rows) a run may hold: 10 minutes at 1.6 kHz — more than a capture
    // records (its longest record, 600 s, at the fastest link's rate).
    static constexpr int MaxSamples = 1000000;
    static QString formatName(); // "drivedesk-run"

    QDateTime created;
    // Drive identity.
    QString family; // "servo-can"
    int address = 0;
    QString model;
    QString firmware;
    // Link: kind ("can", "serial"), a description ("virtualcan:can0 1000000 bit/s").
    QString linkKind;
    QString linkDescription;
    // What was done: "capture", or the step test ("velocity-step", "position-step", "reversal")
    // with its size.
    QString test = QStringLiteral("capture");
    QJsonObject testParameters; // {"speed": 500, "duration": 0.5, ...}
    CaptureSettings settings;
    QStringList units; // one per channel ("r/min", "A", ...)
    CaptureData capture;
    StepMetrics metrics;
    QString metricsChannel; // the response the metrics measure ("" when none were computed)
    QList<TuningSnapshotEntry> tuning;
    QString notes;
    // How the test ended: "" (a capture, or a file from before this field), "completed" or
    // "aborted" — an aborted step test's run holds its record up to the end, with the
    // cause (StepResult::abortCause) and the reason (translated).
    QString outcome;
    QString abortCause;
    QString abortReason;

    QJsonObject toJson() const;
    QByteArray toBytes() const;
    static Error fromJson(const QJsonObject &root, const QString &source, TuningRun *out);
    static Error fromBytes(const QByteArray &bytes, const QString &source, TuningRun *out);

    Error save(const QString &path) const;
    static Error load(const QString &path, TuningRun *out);

    // A short name for lists: the file's base name or "velocity-step 12:03:41".
    QString label;
};

} // namespace dd
