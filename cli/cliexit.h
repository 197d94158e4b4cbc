#pragma once

#include "core/common/error.h"

namespace dd {

// The CLI's exit codes: part of its surface (users' scripts depend on them).
enum class CliExit : int {
    Ok = 0,          // success
    DriveFailed = 1, // the drive or the protocol failed (timeout, exception, verify mismatch)
    Usage = 2,       // bad usage or bad input; nothing was sent
    OpenFailed = 3   // the port or bus could not be opened
};

// The exit code for an error met while talking to a drive: validation failures (nothing
// was sent) are bad input, a port that cannot be opened is 3, everything else is 1.
inline CliExit exitFor(const Error &e)
{
    switch (e.code) {
    case ErrorCode::None: return CliExit::Ok;
    case ErrorCode::OutOfRange:
    case ErrorCode::InvalidArgument:
    case ErrorCode::NotSupported: return CliExit::Usage; // refused before anything was sent
    case ErrorCode::OpenFailed: return CliExit::OpenFailed;
    default: return CliExit::DriveFailed;
    }
}

} // namespace dd
