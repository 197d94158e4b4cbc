// Parameter-dictionary loader, ParameterDictionary::loadFromJson
// (core/params/parameterdictionary.h).
// Input: the file's bytes (seeds: tests/data/dictionaries/, resources/dictionaries/).
// The dictionary already holds the bundled servo-can dictionary when the input is loaded.
// Invariants: a failed load leaves that dictionary unchanged and says why; a loaded one is
// non-empty, sorted by index, its lookups find every entry by index, key and user text, and
// its ranges are consistent with validateValue(); loading it again expecting its own family
// succeeds, expecting another family fails.

#include "tests/fuzz/fuzzsupport.h"

#include "core/params/parameterdictionary.h"

#include <QLocale>

using namespace dd;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    const QByteArray json(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size));

    static const ParameterDictionary &bundled = ParameterDictionary::bundled(Family::ServoCan);
    DD_FUZZ_CHECK(!bundled.isEmpty());
    ParameterDictionary dict = bundled;
    const Error e = dict.loadFromJson(json, QStringLiteral("fuzz.json"));
    if (e) {
        DD_FUZZ_CHECK(!e.message.isEmpty());
        DD_FUZZ_CHECK(dict.size() == bundled.size() && dict.family() == bundled.family()
                      && dict.sourceName() == bundled.sourceName());
        return 0;
    }
    DD_FUZZ_CHECK(!dict.isEmpty() && dict.sourceName() == QStringLiteral("fuzz.json"));
    for (const Family family : {Family::ServoCan, Family::ServoModbus, Family::Shuoke}) {
        ParameterDictionary expecting;
        const Error again = expecting.loadFromJson(json, QStringLiteral("again.json"), family);
        DD_FUZZ_CHECK(bool(again) == (family != dict.family()));
        DD_FUZZ_CHECK(!again || again.code == ErrorCode::InvalidArgument);
    }
    int previous = -1;
    for (const ParameterInfo &p : dict.parameters()) {
        DD_FUZZ_CHECK(p.index > previous && p.index <= ParameterDictionary::MaxIndex);
        previous = p.index;
        DD_FUZZ_CHECK(dict.byIndex(p.index) == &p);
        DD_FUZZ_CHECK(dict.byKey(p.key) == &p && dict.find(p.key) == &p);
        int resolved = -1;
        DD_FUZZ_CHECK(!dict.resolve(p.key, &resolved) && resolved == p.index);
        DD_FUZZ_CHECK(p.min <= p.max && p.min >= valueTypeMin(p.type) && p.max <= valueTypeMax(p.type));
        DD_FUZZ_CHECK(!p.defaultValue || p.inRange(*p.defaultValue));
        DD_FUZZ_CHECK(!dict.validateValue(p.index, p.min) && !dict.validateValue(p.index, p.max));
        DD_FUZZ_CHECK(dict.validateValue(p.index, p.min - 1) && dict.validateValue(p.index, p.max + 1));
        DD_FUZZ_CHECK(bool(dict.validateWrite(p.index, p.min)) == !p.isWritable());
        DD_FUZZ_CHECK(!p.name.english().isEmpty() && !dict.label(p.index, QLocale::c()).isEmpty());
        DD_FUZZ_CHECK(!dict.displayName(p.index, QLocale(QLocale::Chinese, QLocale::China)).isEmpty());
        if (const ParameterInfo *byName = dict.byName(p.name.english())) {
            const QString folded = p.name.english().trimmed().toCaseFolded();
            bool named = false;
            for (const QString &n : byName->name.allTexts())
                named = named || n.trimmed().toCaseFolded() == folded;
            DD_FUZZ_CHECK(named);
        }
    }
    DD_FUZZ_CHECK(dict.indices().size() == dict.size());
    return 0;
}
