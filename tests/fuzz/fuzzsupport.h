#pragma once

// Shared by the libFuzzer targets in tests/fuzz (one fuzz_*.cpp per parser or decoder).
//
// Each target defines LLVMFuzzerTestOneInput. Built with clang and DRIVEDESK_FUZZ it links
// libFuzzer's main; otherwise (any compiler, test builds) it links replaymain.cpp, which runs
// the committed corpus once as a ctest test (fuzz_<name>_corpus).
//
// Input layout: most targets read a few leading "control" bytes (options, mode, a request to
// match) with FuzzInput and pass the rest to the code under test; each target's comment says
// which. Seeds live in tests/fuzz/corpus/<target>/ (tests/fuzz/make-seeds.py writes them).

#include <QByteArray>
#include <QtGlobal>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

// An invariant the code under test must keep. Aborts (libFuzzer saves the input as a crash)
// with the condition's text; unlike Q_ASSERT it is active in every build type.
#define DD_FUZZ_CHECK(cond)                                                                                            \
    do {                                                                                                               \
        if (!(cond)) {                                                                                                 \
            std::fprintf(stderr, "fuzz invariant failed: %s (%s:%d)\n", #cond, __FILE__, __LINE__);                    \
            std::abort();                                                                                              \
        }                                                                                                              \
    } while (0)

namespace dd::fuzz {

// Reads control values from the front of a fuzz input; past the end it yields zeros.
class FuzzInput
{
public:
    FuzzInput(const uint8_t *data, size_t size)
        : m_p(data)
        , m_n(size)
    {
    }

    quint8 byte()
    {
        if (m_n == 0)
            return 0;
        --m_n;
        return *m_p++;
    }
    quint16 u16()
    {
        const quint16 lo = byte();
        return static_cast<quint16>(lo | (byte() << 8));
    }
    quint32 u32()
    {
        const quint32 lo = u16();
        return lo | (static_cast<quint32>(u16()) << 16);
    }
    QByteArray take(size_t n)
    {
        n = n < m_n ? n : m_n;
        QByteArray out(reinterpret_cast<const char *>(m_p), static_cast<qsizetype>(n));
        m_p += n;
        m_n -= n;
        return out;
    }
    QByteArray rest() { return take(m_n); }
    size_t remaining() const { return m_n; }

private:
    const uint8_t *m_p;
    size_t m_n;
};

// Frames behind a CRC are out of a mutation-based fuzzer's reach: almost no mutated frame
// has a valid CRC, so the checks after it would never run. The targets therefore offer
// modes (a control bit) that repair the CRC of what the fuzzer produced.

// `bytes` with its last two bytes replaced by the CRC-16/MODBUS of the bytes before them.
QByteArray withRepairedCrc(const QByteArray &bytes);

// A byte stream built from segments [h][h & 0x7F bytes]: with bit 7 of h set the segment
// gets its CRC-16/MODBUS appended (a frame), else it is copied as it is (noise, truncated
// frames). Reads `in` to its end.
QByteArray segmentsWithCrc(FuzzInput &in);

// Once per process: silences Qt's debug / info / warning output (the loaders log on every
// rejected input, which would slow fuzzing to a crawl); fatal messages still print and
// abort. Registers drivedesk_core's resources (bundled dictionaries).
void initialise();

} // namespace dd::fuzz
