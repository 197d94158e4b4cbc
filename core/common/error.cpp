#include "core/common/error.h"

namespace dd {

QString errorCodeName(ErrorCode code)
{
    switch (code) {
    case ErrorCode::None: return QStringLiteral("none");
    case ErrorCode::Timeout: return QStringLiteral("timeout");
    case ErrorCode::ChecksumError: return QStringLiteral("checksum");
    case ErrorCode::Malformed: return QStringLiteral("malformed");
    case ErrorCode::DriveException: return QStringLiteral("drive-exception");
    case ErrorCode::VerifyMismatch: return QStringLiteral("verify-mismatch");
    case ErrorCode::OutOfRange: return QStringLiteral("out-of-range");
    case ErrorCode::InvalidArgument: return QStringLiteral("invalid-argument");
    case ErrorCode::NotSupported: return QStringLiteral("not-supported");
    case ErrorCode::LinkClosed: return QStringLiteral("link-closed");
    case ErrorCode::OpenFailed: return QStringLiteral("open-failed");
    case ErrorCode::Busy: return QStringLiteral("busy");
    case ErrorCode::Cancelled: return QStringLiteral("cancelled");
    case ErrorCode::FileError: return QStringLiteral("file-error");
    }
    return QStringLiteral("unknown");
}

} // namespace dd
