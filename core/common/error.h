#pragma once

#include <QMetaType>
#include <QString>

namespace dd {

// Typed error of every layer. `message` is translated text for the user: what failed,
// where, and what to try.
enum class ErrorCode {
    None = 0,
    Timeout,         // no (valid) reply in time
    ChecksumError,   // CRC / LRC mismatch
    Malformed,       // frame or file structurally wrong
    DriveException,  // the drive answered with an exception / failure code
    VerifyMismatch,  // read-back differs from what was written
    OutOfRange,      // a value outside its allowed range (nothing was sent)
    InvalidArgument, // bad input from the caller (nothing was sent)
    NotSupported,    // the family / firmware has no such operation
    LinkClosed,      // the port or bus went away
    OpenFailed,      // the port or bus could not be opened
    Busy,            // another operation holds the link
    Cancelled,       // stopped by the user or by a disconnect
    FileError        // a file could not be read or written
};

struct Error
{
    ErrorCode code = ErrorCode::None;
    QString message;
    int driveCode = 0; // exception / failure / alarm code reported by the drive, if any

    bool isError() const { return code != ErrorCode::None; }
    explicit operator bool() const { return isError(); }
    static Error none() { return {}; }
};

QString errorCodeName(ErrorCode code); // stable English identifier, e.g. "timeout"

} // namespace dd

Q_DECLARE_METATYPE(dd::Error)
