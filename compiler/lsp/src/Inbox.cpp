#include "Inbox.h"

#include "voxc/lsp/Transport.h"

#include <fmt/format.h>
#include <string_view>
#include <thread>

namespace voxc::lsp {

namespace {

// nlohmann's parser recurses per nesting level: deeper input is refused before parsing, so a
// message of a million '[' cannot exhaust the stack.
constexpr int kMaxJsonNesting = 256;

bool nestingWithinLimit(std::string_view body) {
    int depth = 0;
    bool inString = false;
    for (size_t i = 0; i < body.size(); ++i) {
        const char c = body[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonNesting) return false;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return true;
}

Incoming parsed(ReadResult read) {
    switch (read.kind) {
    case ReadResult::Kind::End: return {Incoming::Kind::End, {}, {}};
    case ReadResult::Kind::Malformed: return {Incoming::Kind::Malformed, {}, std::move(read.error)};
    case ReadResult::Kind::Message: break;
    }
    if (!nestingWithinLimit(read.body))
        return {Incoming::Kind::Malformed, {}, fmt::format("JSON nested deeper than {} levels", kMaxJsonNesting)};
    nlohmann::json message = nlohmann::json::parse(read.body, nullptr, false);
    if (message.is_discarded()) return {Incoming::Kind::Malformed, {}, "the message is not valid JSON"};
    return {Incoming::Kind::Message, std::move(message), {}};
}

} // namespace

Inbox::Inbox(std::istream& in) : queue_(std::make_shared<Queue>()) {
    // std::cin flushes std::cout before each read: from this thread that would race the
    // server's writes.
    in.tie(nullptr);
    std::thread([queue = queue_, &in] {
        for (bool more = true; more;) {
            Incoming item = parsed(readMessage(in));
            more = item.kind != Incoming::Kind::End;
            const std::lock_guard lock(queue->mutex);
            queue->items.push_back(std::move(item));
            queue->ready.notify_one();
        }
    }).detach();
}

Incoming Inbox::next() {
    std::unique_lock lock(queue_->mutex);
    queue_->ready.wait(lock, [&] { return !queue_->items.empty(); });
    Incoming item = std::move(queue_->items.front());
    queue_->items.pop_front();
    return item;
}

bool Inbox::changeWaiting(const std::string& uri) const {
    const std::lock_guard lock(queue_->mutex);
    for (const Incoming& item : queue_->items) {
        if (item.kind != Incoming::Kind::Message || !item.message.is_object()) continue;
        const nlohmann::json& method = item.message.value("method", nlohmann::json());
        if (method != "textDocument/didChange" && method != "textDocument/didClose") continue;
        const nlohmann::json* params = item.message.contains("params") ? &item.message["params"] : nullptr;
        if (params && params->is_object() && params->contains("textDocument") && (*params)["textDocument"].is_object() &&
            (*params)["textDocument"].value("uri", nlohmann::json()) == uri)
            return true;
    }
    return false;
}

} // namespace voxc::lsp
