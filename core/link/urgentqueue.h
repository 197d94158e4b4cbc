#pragma once

#include <QQueue>

#include <utility>

namespace dd {

// Queues `pending` (anything with a `request.urgent` flag) for a link: an ordinary request
// at the end; an urgent one (stop, emergency stop, disable) ahead of every ordinary request
// waiting, behind the urgent ones already there, so that urgent requests keep the order
// they came in. The request on the wire is not in the queue: it is never overtaken.
template <typename Pending>
void enqueueByUrgency(QQueue<Pending> &queue, Pending pending)
{
    qsizetype at = queue.size();
    if (pending.request.urgent) {
        at = 0;
        while (at < queue.size() && queue.at(at).request.urgent)
            ++at;
    }
    queue.insert(at, std::move(pending));
}

} // namespace dd
