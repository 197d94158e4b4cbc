// Alarm-table loader, AlarmDictionary::loadFromJson (core/params/alarmdictionary.h).
// Input: the file's bytes (seeds: tests/data/alarms/, resources/alarms/).
// Invariants: a failed load leaves the table unloaded and says why; a loaded table has a
// non-empty English and Chinese text for every listed code and, through the fallback
// template, for any other code; loading it again expecting its own family succeeds,
// expecting another family fails.

#include "tests/fuzz/fuzzsupport.h"

#include "core/params/alarmdictionary.h"

#include <QLocale>

using namespace dd;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    const QByteArray json(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size));

    AlarmDictionary alarms;
    const Error e = alarms.loadFromJson(json, QStringLiteral("fuzz.json"));
    if (e) {
        DD_FUZZ_CHECK(!e.message.isEmpty());
        DD_FUZZ_CHECK(!alarms.isLoaded() && alarms.size() == 0);
        return 0;
    }
    DD_FUZZ_CHECK(alarms.isLoaded());
    for (const Family family : {Family::ServoCan, Family::ServoModbus, Family::Shuoke}) {
        AlarmDictionary expecting;
        const Error again = expecting.loadFromJson(json, QStringLiteral("again.json"), family);
        DD_FUZZ_CHECK(bool(again) == (family != alarms.family()));
        DD_FUZZ_CHECK(!again || again.code == ErrorCode::InvalidArgument);
    }
    static const QLocale english = QLocale::c();
    static const QLocale chinese(QLocale::Chinese, QLocale::China);
    const QList<qint64> codes = alarms.codes();
    DD_FUZZ_CHECK(codes.size() == alarms.size());
    for (const qint64 code : codes) {
        const AlarmDictionary::Alarm *a = alarms.alarm(code);
        DD_FUZZ_CHECK(a && a->code == code && alarms.contains(code));
        DD_FUZZ_CHECK(!alarms.text(code, english).isEmpty() && !alarms.text(code, chinese).isEmpty());
        (void)alarms.remedy(code, chinese);
    }
    for (const qint64 code : {qint64(0), qint64(-1), qint64(65535), qint64(std::numeric_limits<qint32>::max()) + 1}) {
        if (!alarms.contains(code)) {
            DD_FUZZ_CHECK(alarms.text(code, english).contains(QString::number(code)));
            DD_FUZZ_CHECK(!alarms.text(code, chinese).isEmpty());
        }
    }
    return 0;
}
