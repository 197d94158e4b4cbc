#include "ui/panels/parameters/parametereditcommand.h"

#include "core/params/parameterdictionary.h"
#include "ui/panels/parameters/parametertablemodel.h"

namespace dd {

ParameterEditCommand::ParameterEditCommand(ParameterTableModel *model, int parameterIndex, std::optional<qint64> before,
                                           std::optional<qint64> after)
    : m_model(model)
    , m_index(parameterIndex)
    , m_before(before)
    , m_after(after)
{
    const QString label = model->dictionary() ? model->dictionary()->label(parameterIndex)
                                              : QStringLiteral("P%1").arg(parameterIndex);
    const std::optional<qint64> shown = after         ? after
        : model->driveValue(parameterIndex).isKnown() ? std::optional<qint64>(model->driveValue(parameterIndex).value)
                                                      : std::nullopt;
    setText(shown ? tr("%1 = %2").arg(label).arg(*shown) : tr("Edit %1").arg(label));
    const ParameterValue drive = model->driveValue(parameterIndex);
    if (drive.source == ValueSource::ReadFromDrive)
        m_driveBefore = drive.value;
}

void ParameterEditCommand::undo()
{
    if (!m_model)
        return;
    // Written since? Then the drive holds the new value: bring the old one back as an edit.
    const ParameterValue now = m_model->driveValue(m_index);
    const bool writtenSince = m_driveBefore && now.source == ValueSource::ReadFromDrive && now.value != *m_driveBefore;
    std::optional<qint64> value = m_before;
    if (!value && writtenSince)
        value = m_driveBefore;
    m_model->setEditedValue(m_index, value, writtenSince);
}

void ParameterEditCommand::redo()
{
    if (m_model)
        m_model->setEditedValue(m_index, m_after);
}

} // namespace dd
