#pragma once

#include "core/common/family.h"

#include <QMenu>

namespace dd {

class DemoLauncher;

// The Demo menu: what a user can do to the simulated drives of the demo bench to try a
// workflow without hardware. Inject alarm → raise an alarm on a demo drive (the families
// whose drives report an alarm code), or let it go, as when its cause is removed; the
// Alarms tab then shows it, in its history since the drive was found, with its text and
// what to check. Entries are made when the menu opens; without a running bench it says how
// to start one.
class DemoMenu : public QMenu
{
    Q_OBJECT
public:
    static constexpr int InjectedCode = 12; // an alarm code the demo raises

    explicit DemoMenu(DemoLauncher *demo, QWidget *parent = nullptr);

    // Raises (code > 0) or removes (0) the alarm of the demo drive of `family`; false when
    // the bench is not running or that drive cannot.
    bool injectAlarm(Family family, int code);
    // Makes the entries again (on opening; tests call it to find them).
    void rebuild();
    QMenu *injectMenu() const { return m_inject; }

protected:
    void changeEvent(QEvent *event) override;

private:
    DemoLauncher *m_demo = nullptr;
    QMenu *m_inject = nullptr;
};

} // namespace dd
