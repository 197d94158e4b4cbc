#pragma once

#include "core/common/error.h"
#include "core/fleet/parametersource.h"

#include <QCoreApplication>
#include <QList>
#include <QVector>
#include <optional>

namespace dd {

class ParameterDictionary;

// Any number of parameter sources side by side (the GUI's Compare view, `diff A B`): one
// row per dictionary parameter that at least one source knows, one value per source.
// A row differs when two of its known values differ; a value one source lacks is shown
// as missing, not as a difference.
class ParameterComparison
{
    Q_DECLARE_TR_FUNCTIONS(dd::ParameterComparison)

public:
    struct Row
    {
        int index = -1;
        QString key;
        QVector<std::optional<qint64>> values; // one per source
        bool differs = false;
        bool missing = false; // some source has no value
        bool communication = false;
    };

    // Sources of different families cannot be compared: the error says which and why.
    static Error checkFamilies(const QList<ParameterSource> &sources);
    static ParameterComparison compute(const ParameterDictionary &dictionary, const QList<ParameterSource> &sources);

    const QList<ParameterSource> &sources() const { return m_sources; }
    const QVector<Row> &rows() const { return m_rows; }
    int differenceCount() const;
    // Whether the sources that report a firmware report different ones.
    bool firmwareDiffers() const;

private:
    QList<ParameterSource> m_sources;
    QVector<Row> m_rows;
};

} // namespace dd
