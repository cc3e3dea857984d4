#pragma once
// The Language Server Protocol's base framing over a byte stream: header lines ending in "\r\n"
// (Content-Length is the one that matters), an empty line, then that many bytes of JSON. Sizes
// are bounded, so a malformed or hostile client costs bounded memory and never hangs the server
// on a message it cannot finish.
#include <cstddef>
#include <istream>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

namespace voxc::lsp {

// A header line longer than this, or more header lines than kMaxHeaderLines, is malformed.
inline constexpr size_t kMaxHeaderLine = 1024;
inline constexpr size_t kMaxHeaderLines = 16;
// The largest message body read: a document at the checker's source cap (4 MiB) as a JSON
// string, escapes included, fits with room to spare.
inline constexpr size_t kMaxContentLength = size_t(32) << 20;

struct ReadResult {
    enum class Kind {
        Message,   // `body` holds one message's bytes
        Malformed, // a bad or missing header, or a body over kMaxContentLength (skipped); `error` says why
        End,       // the stream ended (between messages, or inside one)
    };
    Kind kind = Kind::End;
    std::string body;
    std::string error;
};

// Reads the next message. After Malformed the stream is positioned after the bad header block
// (and after its body, when its length was known), so reading can go on.
ReadResult readMessage(std::istream& in);

// Writes one message with its Content-Length header and flushes.
void writeMessage(std::ostream& out, std::string_view body);

} // namespace voxc::lsp
