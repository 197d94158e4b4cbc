#pragma once

#include <QByteArray>
#include <QString>
#include <QtGlobal>

#include <optional>
#include <random>

namespace dd {

// What can go wrong between a simulated drive and the host. The buses apply it to what the
// drive sends (replies on a serial bus, every frame on CAN):
//   - drop:    the frame is never sent (the host times out)
//   - corrupt: one random bit of one random byte is flipped (the host must see a bad CRC /
//              a wrong value; on CAN, real hardware would reject such a frame by its CRC, so
//              there this models a faulty drive rather than line noise)
//   - latency: extra delay before the frame leaves: fixed + uniform 0..jitter
//   - silent:  power loss: the drive neither hears nor sends anything
struct FaultSettings
{
    double dropRate = 0.0;    // 0..1, probability per frame
    double corruptRate = 0.0; // 0..1, probability per frame
    int extraLatencyMs = 0;   // fixed extra delay, ms
    int latencyJitterMs = 0;  // plus uniform 0..jitter ms
    bool silent = false;
    quint32 seed = 1;

    // Parses "drop=0.1,corrupt=0.02,latency=20,jitter=5,silent,seed=7" (keys in any order,
    // all optional; "silent" alone or silent=0/1). Percentages are accepted for the rates
    // ("drop=10%"). On error returns nullopt and, when `error` is given, a technical
    // English message naming the bad item.
    static std::optional<FaultSettings> parse(const QString &spec, QString *error = nullptr);
    // The same notation; parse(toString()) reproduces the settings.
    QString toString() const;

    bool operator==(const FaultSettings &o) const;
    bool operator!=(const FaultSettings &o) const { return !(*this == o); }
};

// Seeded fault decisions. Each call of dropNow(), corrupt() and extraLatencyMs() consumes a
// fixed number of draws of a std::mt19937 (whose output the standard fixes), and the draws
// are turned into decisions without the library's distributions, so a given seed and call
// sequence gives the same faults on every platform and compiler.
class FaultInjector
{
public:
    FaultInjector();
    explicit FaultInjector(const FaultSettings &settings);

    const FaultSettings &settings() const { return m_settings; }
    // Replaces the settings and restarts the random sequence from settings.seed.
    void setSettings(const FaultSettings &settings);
    void reseed(quint32 seed);

    void setDropRate(double rate);
    void setCorruptRate(double rate);
    void setExtraLatency(int fixedMs, int jitterMs = 0);
    void setSilent(bool silent) { m_settings.silent = silent; }
    bool isSilent() const { return m_settings.silent; }

    // One decision: true with probability dropRate (one draw).
    bool dropNow();
    // With probability corruptRate returns `bytes` with one random bit of one random byte
    // flipped, otherwise `bytes` unchanged (three draws either way; empty input unchanged).
    QByteArray corrupt(QByteArray bytes);
    // True when the last corrupt() call changed its input.
    bool lastCorrupted() const { return m_lastCorrupted; }
    // extraLatencyMs + uniform integer in 0..latencyJitterMs (one draw).
    int extraLatencyMs();

private:
    double uniform();         // [0, 1) from one 32-bit draw
    quint32 below(quint32 n); // 0..n-1 from one 32-bit draw (n > 0)

    FaultSettings m_settings;
    std::mt19937 m_rng;
    bool m_lastCorrupted = false;
};

} // namespace dd
