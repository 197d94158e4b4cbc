#pragma once

#include "core/common/error.h"
#include "core/fleet/parametersource.h"

#include <QDialog>
#include <QList>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace dd {

class DriveDirectory;
class ParameterDictionary;

// Compare parameters: any sources side by side — drives on the open links (read live),
// backup files, the dictionary's defaults — one row per parameter, one column per source.
// Rows that differ are highlighted; "Only differences" and the search narrow the rows;
// the table exports to CSV. Sources of another family than the first are refused with the
// reason; a firmware that differs between sources is said above the table.
class CompareView : public QDialog
{
    Q_OBJECT
public:
    explicit CompareView(DriveDirectory *directory, QWidget *parent = nullptr);
    ~CompareView() override;

    // Adds a source; an error (shown in the view too) when it cannot be compared.
    Error addFile(const QString &path);
    Error addDefaults(Family family);
    // Reads the drive through the hub; sourcesChanged() or failed() follows.
    void addDrive(int connectionId, int address);
    void removeSource(int column);

    const QList<ParameterSource> &sources() const { return m_sources; }
    int differenceCount() const;
    QString message() const; // the status line: refusals, firmware differences
    QTableWidget *table() const { return m_table; }
    void setOnlyDifferences(bool on);
    void setSearchText(const QString &text);
    Error exportCsv(const QString &path) const;

signals:
    void sourcesChanged();
    void failed(const dd::Error &error);

protected:
    void changeEvent(QEvent *event) override;

private:
    Error add(const ParameterSource &source);
    void rebuild();
    void applyFilter();
    void retranslate();
    void showError(const Error &error);
    void chooseDrive();
    void chooseFile();
    void chooseExport();
    const ParameterDictionary &dictionary() const;

    DriveDirectory *m_directory = nullptr;
    QList<ParameterSource> m_sources;
    QPushButton *m_addDrive = nullptr;
    QPushButton *m_addFile = nullptr;
    QPushButton *m_addDefaults = nullptr;
    QPushButton *m_export = nullptr;
    QCheckBox *m_onlyDifferences = nullptr;
    QLineEdit *m_search = nullptr;
    QLabel *m_message = nullptr;
    QTableWidget *m_table = nullptr;
    QString m_error;
    int m_pending = 0; // drive reads under way
};

} // namespace dd
