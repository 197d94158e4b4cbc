#pragma once

// For the GUI tests of drive panels: one simulated bus (SimBenchThread), a DriveHub connected
// to it, and the shell's DriveDirectory + DriveWorkspace showing the tabs of the drive at
// address 1 in an active window — the panels are created and fed as in the application.

#include "core/drive/drivehub.h"
#include "tests/gui/simbenchthread.h"
#include "ui/bus/drivedirectory.h"
#include "ui/workspace/drivepanel.h"
#include "ui/workspace/driveworkspace.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTabWidget>
#include <QTest>
#include <functional>
#include <memory>

class PanelRig
{
public:
    using CanHook = std::function<void(const dd::CanFrameData &frame)>;

    QElapsedTimer clock; // started by start()
    SimBenchThread sim;
    std::unique_ptr<dd::DriveHub> hub;
    std::unique_ptr<dd::DriveDirectory> directory;
    std::unique_ptr<dd::DriveWorkspace> workspace;
    int id = 0;

    ~PanelRig()
    {
        workspace.reset();
        directory.reset();
        hub.reset();
    }

    // `hook` (CAN benches) sees every frame the simulated drives receive, on the bench
    // thread: capture only what outlives the rig (shared pointers, atomics).
    bool start(const dd::SimBenchOptions &options, QString *why, CanHook hook = {})
    {
        clock.start();
        if (const dd::Error e = sim.start(options)) {
            *why = e.message;
            return false;
        }
        if (!options.can.isEmpty()) {
            if (!waitUntil([&] { return sim.call([&] { return sim.bench()->canBus()->isConnected(); }); }, 5000)) {
                *why = QStringLiteral("the simulated CAN bus did not connect");
                return false;
            }
            if (hook)
                sim.call([this, hook] {
                    QObject::connect(sim.bench()->canBus(), &dd::SimCanBus::frameReceived, sim.context(),
                                     [hook](const dd::CanFrameData &f, qint64) { hook(f); });
                });
        }
        hub = std::make_unique<dd::DriveHub>();
        directory = std::make_unique<dd::DriveDirectory>(hub.get());
        workspace = std::make_unique<dd::DriveWorkspace>(directory.get());
        const dd::ConnectionSettings settings = sim.clientSettings();
        dd::Error openError;
        bool opened = false;
        hub->openConnection(settings, [&](int newId, const dd::Error &e) {
            id = newId;
            openError = e;
            opened = true;
        });
        if (!waitUntil([&] { return opened; }, 5000) || id <= 0) {
            *why = QStringLiteral("open failed: ") + openError.message;
            return false;
        }
        directory->addConnection(id, settings);
        dd::DiscoveredDrive found;
        found.family = options.family;
        found.address = 1;
        directory->addDrive(id, found);
        workspace->showDrive(id, 1);
        workspace->resize(900, 600);
        workspace->show();
        QApplication::setActiveWindow(workspace.get());
        if (!QTest::qWaitForWindowActive(workspace.get())) {
            *why = QStringLiteral("the window did not become active");
            return false;
        }
        return true;
    }

    // The drive's panel of type P, made the current tab; waits for the drive's description.
    template <typename P>
    P *show(QString *why)
    {
        P *panel = nullptr;
        for (dd::DrivePanel *p : workspace->panelsFor(id, 1))
            if (auto *candidate = qobject_cast<P *>(p))
                panel = candidate;
        if (!panel) {
            *why = QStringLiteral("no such tab");
            return nullptr;
        }
        workspace->tabsFor(id, 1)->setCurrentWidget(panel);
        if (!waitUntil([&] { return panel->driveInfo().valid; }, 5000)) {
            *why = QStringLiteral("no drive description");
            return nullptr;
        }
        return panel;
    }
};
