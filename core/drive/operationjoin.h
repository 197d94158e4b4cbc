#pragma once

#include "core/common/error.h"

#include <functional>
#include <memory>

namespace dd {

// Joins a known number of asynchronous operations: complete() once per operation; after the
// last one `done` is called once with the first error (or none). Progress is reported after
// each completion. Held by shared_ptr in the operations' callbacks.
class OperationJoin
{
public:
    using Done = std::function<void(const Error &)>;
    using Progress = std::function<void(int done, int total)>;

    static std::shared_ptr<OperationJoin> create(int count, Done done, Progress progress = {})
    {
        auto j = std::make_shared<OperationJoin>();
        j->m_pending = count;
        j->m_total = count;
        j->m_done = std::move(done);
        j->m_progress = std::move(progress);
        if (count == 0 && j->m_done)
            j->m_done(Error::none());
        return j;
    }

    void complete(const Error &e = Error::none())
    {
        if (m_pending <= 0)
            return;
        if (e.isError() && !m_first.isError())
            m_first = e;
        ++m_completed;
        if (m_progress)
            m_progress(m_completed, m_total);
        if (--m_pending == 0 && m_done)
            m_done(m_first);
    }

    int total() const { return m_total; }
    int completed() const { return m_completed; }

private:
    int m_pending = 0;
    int m_total = 0;
    int m_completed = 0;
    Error m_first;
    Done m_done;
    Progress m_progress;
};

} // namespace dd
