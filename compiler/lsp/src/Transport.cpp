#include "voxc/lsp/Transport.h"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace voxc::lsp {

namespace {

enum class LineStatus { Ok, TooLong, End };

// One header line without its "\r\n" (a bare "\n" is accepted too).
LineStatus readHeaderLine(std::istream& in, std::string& line) {
    line.clear();
    for (int c; (c = in.get()) != std::char_traits<char>::eof();) {
        if (c == '\n') {
            if (!line.empty() && line.back() == '\r') line.pop_back();
            return LineStatus::Ok;
        }
        if (line.size() == kMaxHeaderLine) {
            // Skip to the end of the line so the next read starts at a line boundary.
            while ((c = in.get()) != std::char_traits<char>::eof() && c != '\n') {}
            return LineStatus::TooLong;
        }
        line.push_back(char(c));
    }
    return LineStatus::End;
}

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

// Discards `count` bytes; false when the stream ends first.
bool skip(std::istream& in, size_t count) {
    char buffer[4096];
    while (count > 0) {
        const size_t chunk = std::min(count, sizeof buffer);
        in.read(buffer, std::streamsize(chunk));
        if (size_t(in.gcount()) != chunk) return false;
        count -= chunk;
    }
    return true;
}

} // namespace

ReadResult readMessage(std::istream& in) {
    std::optional<size_t> length;
    std::string error;
    std::string line;
    size_t lines = 0;
    for (;;) {
        const LineStatus status = readHeaderLine(in, line);
        if (status == LineStatus::End) return {ReadResult::Kind::End, {}, {}};
        if (status == LineStatus::Ok && line.empty()) {
            if (lines == 0) continue; // blank lines between messages
            break;
        }
        // A bad line makes the message malformed, but a Content-Length after it still says how
        // much body to read past.
        if (++lines > kMaxHeaderLines && error.empty()) error = "more than 16 header lines";
        if (status == LineStatus::TooLong) {
            error = "a header line is longer than 1024 bytes";
            continue;
        }
        const size_t colon = line.find(':');
        if (colon == std::string::npos) {
            error = "a header line without ':'";
            continue;
        }
        if (!equalsIgnoringCase(std::string_view(line).substr(0, colon), "Content-Length")) continue;
        std::string_view value = std::string_view(line).substr(colon + 1);
        while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
        while (!value.empty() && value.back() == ' ') value.remove_suffix(1);
        size_t parsed = 0;
        const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), parsed);
        if (ec != std::errc() || end != value.data() + value.size() || value.empty())
            error = "Content-Length is not a number";
        else
            length = parsed;
    }
    if (!error.empty()) {
        if (length && !skip(in, *length)) return {ReadResult::Kind::End, {}, {}};
        return {ReadResult::Kind::Malformed, {}, error};
    }
    if (!length) return {ReadResult::Kind::Malformed, {}, "a message without Content-Length"};
    if (*length > kMaxContentLength) {
        if (!skip(in, *length)) return {ReadResult::Kind::End, {}, {}};
        return {ReadResult::Kind::Malformed, {}, "a message larger than 32 MiB (skipped)"};
    }
    std::string body(*length, '\0');
    in.read(body.data(), std::streamsize(body.size()));
    if (size_t(in.gcount()) != body.size()) return {ReadResult::Kind::End, {}, {}};
    return {ReadResult::Kind::Message, std::move(body), {}};
}

void writeMessage(std::ostream& out, std::string_view body) {
    out << "Content-Length: " << body.size() << "\r\n\r\n" << body;
    out.flush();
}

} // namespace voxc::lsp
