#pragma once

#include "core/common/family.h"
#include "core/drive/drivetypes.h"

#include <QList>
#include <QObject>
#include <QString>

namespace dd {

class DriveDirectory;

// What STOP did, drive by drive. After DriveHub::stopAll() has been posted, start() reads the
// state of every drive in the directory until it reports the axis at rest (or gives up) and
// classifies each:
//   Stopped        the family has a stop command and the drive now reports no motion;
//   AtRest         the family has no stop command (servo-modbus), but the drive is at rest;
//   NotSupported   the family has no stop command and the drive still moves: nothing could
//                  be done from DriveDesk (the machine's emergency stop or the drive's own
//                  inputs must stop it);
//   Failed         the stop could not be confirmed: no answer, or still moving.
// The texts are made when asked for (summary(), lineText()), so they follow a language switch.
class StopReporter : public QObject
{
    Q_OBJECT
public:
    enum class Outcome { Pending, Stopped, AtRest, NotSupported, Failed };
    struct Line
    {
        int connectionId = 0;
        int address = 0;
        Family family = Family::ServoModbus;
        bool hasStop = true;
        bool wasEnabled = false; // the power stage was on when STOP was sent
        Outcome outcome = Outcome::Pending;
        QString error; // translated, from the drive layer (Failed)
        int reads = 0;
        DriveStatus status; // as last read
    };

    explicit StopReporter(DriveDirectory *directory, QObject *parent = nullptr);

    // How long a drive with a stop command may take to report rest.
    static constexpr int ConfirmTimeoutMs = 2000;
    static constexpr int PollIntervalMs = 100;

    void start();
    bool isRunning() const { return m_pending > 0; }
    QList<Line> lines() const { return m_lines; }
    // "STOP: …" — one sentence per drive (or "sent, no drive connected").
    QString summary() const;
    // The same, one drive a line, with a heading: for the report's tooltip and window.
    QString details() const;
    static QString lineText(const Line &line);

signals:
    void updated();  // a drive's outcome is known
    void finished(); // every drive's outcome is known

private:
    void poll(int generation, int index);
    void settle(int index, Outcome outcome, const QString &error = {});

    DriveDirectory *m_directory = nullptr;
    QList<Line> m_lines;
    int m_pending = 0;
    int m_generation = 0;
    bool m_started = false;
};

} // namespace dd
