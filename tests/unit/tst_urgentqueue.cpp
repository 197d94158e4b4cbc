// enqueueByUrgency: the one queue rule of SerialLink, CanLink and ModbusLink.
#include "core/link/urgentqueue.h"

#include <QtTest>

using namespace dd;

namespace {

struct Request
{
    int id = 0;
    bool urgent = false;
};
struct Pending
{
    Request request;
};

QList<int> ids(const QQueue<Pending> &queue)
{
    QList<int> out;
    for (const Pending &p : queue)
        out << p.request.id;
    return out;
}

} // namespace

class TestUrgentQueue : public QObject
{
    Q_OBJECT

private slots:
    void ordinaryRequestsKeepTheirOrder()
    {
        QQueue<Pending> q;
        for (int id = 1; id <= 3; ++id)
            enqueueByUrgency(q, Pending{{id, false}});
        QCOMPARE(ids(q), (QList<int>{1, 2, 3}));
    }

    void urgentGoesAheadOfOrdinary()
    {
        QQueue<Pending> q;
        enqueueByUrgency(q, Pending{{1, false}});
        enqueueByUrgency(q, Pending{{2, false}});
        enqueueByUrgency(q, Pending{{10, true}});
        QCOMPARE(ids(q), (QList<int>{10, 1, 2}));
    }

    void urgentOnesKeepTheOrderTheyCameIn()
    {
        QQueue<Pending> q;
        enqueueByUrgency(q, Pending{{1, false}});
        enqueueByUrgency(q, Pending{{10, true}});
        enqueueByUrgency(q, Pending{{2, false}});
        enqueueByUrgency(q, Pending{{11, true}});
        enqueueByUrgency(q, Pending{{12, true}});
        QCOMPARE(ids(q), (QList<int>{10, 11, 12, 1, 2}));
    }

    void urgentIntoAnEmptyQueue()
    {
        QQueue<Pending> q;
        enqueueByUrgency(q, Pending{{10, true}});
        enqueueByUrgency(q, Pending{{1, false}});
        QCOMPARE(ids(q), (QList<int>{10, 1}));
    }
};

QTEST_GUILESS_MAIN(TestUrgentQueue)
#include "tst_urgentqueue.moc"
