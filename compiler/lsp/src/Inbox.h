#pragma once
// Messages read ahead of the server on a thread of their own, parsed: while a check runs (a
// terrain's solve can take seconds), the edits typed meanwhile queue up here, and the server
// skips checking a document whose newer edit is already waiting (docs/editors.md).
#include <condition_variable>
#include <deque>
#include <istream>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>

namespace voxc::lsp {

struct Incoming {
    enum class Kind { Message, Malformed, End };
    Kind kind = Kind::End;
    nlohmann::json message; // Kind::Message: the parsed message
    std::string error;      // Kind::Malformed: why (bad framing, bad JSON, too deep)
};

class Inbox {
public:
    // Starts reading `in` until its end; `in` must outlive the reading (the process's stdin does).
    explicit Inbox(std::istream& in);

    // The next message, waiting for one.
    Incoming next();
    // Whether a didChange or didClose of `uri` is waiting.
    bool changeWaiting(const std::string& uri) const;

private:
    // Shared with the reading thread, which is detached: at `exit` it may be blocked on a read.
    struct Queue {
        mutable std::mutex mutex;
        std::condition_variable ready;
        std::deque<Incoming> items;
    };
    std::shared_ptr<Queue> queue_;
};

} // namespace voxc::lsp
