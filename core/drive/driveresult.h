#pragma once

#include "core/common/error.h"
#include "core/drive/drivetypes.h"

#include <QMap>
#include <QMetaType>
#include <QVariantMap>

namespace dd {

class DriveReply;

// A DriveReply's outcome as a value, so that it can cross threads (DriveHub).
struct DriveResult
{
    Error error;
    QMap<int, qint64> parameters;
    QList<ParameterWriteResult> writes;
    QMap<QString, double> samples;
    qint64 sampleTimeUs = 0;
    DriveStatus status;
    QVariantMap info;
    // DriveHub::run: the drive's identity when the operation finished (for the verification
    // journal's key); empty from DriveResult::from.
    DriveIdentity identity;

    bool ok() const { return !error.isError(); }
    static DriveResult from(const DriveReply &reply);
};

} // namespace dd

Q_DECLARE_METATYPE(dd::DriveResult)
