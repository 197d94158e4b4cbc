#pragma once

// Checks shared by the Shuoke fuzz targets.

#include "fuzzsupport.h"

#include "protocol/shuokecommands.h"
#include "protocol/shuokeframe.h"
#include "protocol/shuokevalues.h"

namespace dd::fuzz {

// The value codecs a drive's data bytes meet after framing: they must not crash on any
// data, and what they decode re-encodes to something that decodes the same.
inline void checkShuokeValues(const shuoke::Frame &f)
{
    using namespace dd::shuoke;
    DD_FUZZ_CHECK(!(f.failure && !f.data.isEmpty()));
    DD_FUZZ_CHECK(!commandName(f.command).isEmpty());
    if (f.failure) {
        DD_FUZZ_CHECK(!failureDescription(f.failureCode).isEmpty());
        return;
    }
    for (ByteOrder order : {ByteOrder::LittleEndian, ByteOrder::BigEndian}) {
        if (const auto v = decodeUInt32(f.data, order))
            DD_FUZZ_CHECK(encodeUInt32(*v, order) == f.data);
        if (const auto v = decodeInt32(f.data, order))
            DD_FUZZ_CHECK(encodeInt32(*v, order) == f.data);
        if (const auto v = decodeUInt16(f.data, order))
            DD_FUZZ_CHECK(encodeUInt16(*v, order) == f.data);
        if (const auto v = decodeDirection24(f.data, order)) {
            const std::optional<QByteArray> again = encodeDirection24(*v, order);
            DD_FUZZ_CHECK(again && decodeDirection24(*again, order) == v);
        }
        (void)validateRequestData(f.command, f.data, order);
    }
    if (const auto s = decodeMotionStatus(f.data))
        DD_FUZZ_CHECK(decodeMotionStatus(encodeMotionStatus(*s)) == s);
    (void)decodeInputBits(f.data);
    (void)acceptedReplyCommands(f);
    (void)isReplyTo(f, f);
}

} // namespace dd::fuzz
