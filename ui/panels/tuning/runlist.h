#pragma once

#include "core/common/error.h"
#include "core/tuning/tuningrun.h"

#include <QWidget>
#include <functional>

class QLabel;
class QListWidget;
class QPushButton;

namespace dd {

// The Tuning tab's runs: this session's captures and step tests and the .ddrun files
// opened, newest last. Each has an overlay tick (the plot and the metrics table show the
// ticked runs, in list order); the selected one is what Save…, the spectrum and "Apply this
// run's parameters" act on. A file that does not load is refused with the reason and the
// list is left as it was.
class RunList : public QWidget
{
    Q_OBJECT
public:
    explicit RunList(QWidget *parent = nullptr);

    // Adds a run (ticked, selected).
    void addRun(const TuningRun &run);
    // Loads a .ddrun; on error the list is unchanged and the message line says why.
    Error openFile(const QString &path);
    // Saves the selected run.
    Error saveSelected(const QString &path);

    int count() const { return int(m_runs.size()); }
    const TuningRun &run(int i) const { return m_runs.at(i); }
    bool isOverlaid(int i) const;
    void setOverlaid(int i, bool on);
    QList<TuningRun> overlaidRuns() const;
    int selectedIndex() const;
    const TuningRun *selectedRun() const;
    void select(int i);
    QString message() const;
    QListWidget *list() const { return m_list; }

signals:
    void overlayChanged();
    void selectionChanged();
    void fileUsed(const QString &path);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void updateButtons();
    void openInteractive();
    void saveInteractive();
    void removeSelected();
    void setMessage(std::function<QString()> text, bool problem);

    QList<TuningRun> m_runs;
    QListWidget *m_list = nullptr;
    QPushButton *m_open = nullptr;
    QPushButton *m_save = nullptr;
    QPushButton *m_remove = nullptr;
    QLabel *m_message = nullptr;
    bool m_filling = false;
};

} // namespace dd
