#include "voxc/lsp/Server.h"

#include "Documents.h"
#include "Inbox.h"
#include "LanguageHelp.h"
#include "voxc/lsp/Transport.h"

#include "voxc/check/Check.h"
#include "voxc/syntax/Ast.h"
#include "voxc/syntax/Parser.h"

#include <condition_variable>
#include <fmt/format.h>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

namespace voxc::lsp {

namespace {

using json = nlohmann::json;

// JSON-RPC error codes (LSP specification, "Response Message").
constexpr int kParseError = -32700;
constexpr int kInvalidRequest = -32600;
constexpr int kMethodNotFound = -32601;
constexpr int kInvalidParams = -32602;
constexpr int kInternalError = -32603;
constexpr int kServerNotInitialized = -32002;

std::string dump(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

json positionJson(Position p) { return {{"line", p.line}, {"character", p.character}}; }

json rangeJson(SourceLoc loc, const SourceFile& file) {
    const std::string_view line = file.line(loc.line);
    return {{"start", positionJson(startOf(loc, line))}, {"end", positionJson(endOf(loc, line))}};
}

bool isWordCharacter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// A name the file declares: constants, functions, fields, features and labelled blocks.
struct Declared {
    std::string name;
    WordKind kind;
    std::string detail;
    SourceLoc loc;
};

void collectBlockNames(const ast::Block& block, std::vector<Declared>& names) {
    if (block.label) names.push_back({*block.label, WordKind::Module, fmt::format("{} block", block.kind), block.labelLoc});
    for (const ast::Block& inner : block.blocks) collectBlockNames(inner, names);
}

std::vector<Declared> declaredNames(const ast::File& file) {
    std::vector<Declared> names;
    for (const ast::ConstDecl& c : file.constants) names.push_back({c.name, WordKind::Variable, "const", c.loc});
    for (const ast::FunctionDecl& f : file.functions) {
        std::string parameters;
        for (const ast::Parameter& p : f.parameters)
            parameters += fmt::format("{}{}: {}", parameters.empty() ? "" : ", ", p.name, p.type);
        names.push_back({f.name, WordKind::Function, fmt::format("fn {}({}) -> {}", f.name, parameters, f.result), f.loc});
    }
    for (const ast::FieldDecl& f : file.fields) names.push_back({f.name, WordKind::Variable, "field", f.loc});
    for (const ast::FeatureDecl& f : file.features)
        names.push_back({f.name, WordKind::Variable, fmt::format("feature ({})", f.body.kind), f.loc});
    for (const ast::Block& block : file.blocks) collectBlockNames(block, names);
    return names;
}

// (line, column), both 1-based as the checker counts.
struct Place {
    uint32_t line;
    uint32_t column;
    auto operator<=>(const Place&) const = default;
};

bool inside(SourceLoc loc, Place place) {
    return loc.line == place.line && place.column >= loc.column && place.column < loc.column + loc.length;
}

// The innermost block around `place` (after its kind word, up to its closing brace), and the
// assignment whose key is at `place`, if any.
struct BlockAt {
    const ast::Block* block = nullptr;
    const ast::Assignment* key = nullptr;
};

void findBlockAt(const ast::Block& block, Place place, BlockAt& found) {
    const Place start{block.loc.line, block.loc.column};
    const bool open = block.end.line == 0;
    if (!(start < place) || (!open && Place{block.end.line, block.end.column} < place)) return;
    found.block = &block;
    for (const ast::Assignment& assignment : block.assignments)
        if (inside(assignment.loc, place)) found.key = &assignment;
    for (const ast::Block& inner : block.blocks) findBlockAt(inner, place, found);
}

BlockAt blockAt(const ast::File& file, Place place) {
    BlockAt found;
    for (const ast::Block& block : file.blocks) findBlockAt(block, place, found);
    for (const ast::FeatureDecl& feature : file.features) findBlockAt(feature.body, place, found);
    return found;
}

json completionItem(const std::string& label, WordKind kind, const std::string& detail, const std::string& doc,
                    const char* sortGroup) {
    json item{{"label", label}, {"kind", int(kind)}, {"detail", detail}, {"sortText", std::string(sortGroup) + label}};
    if (!doc.empty()) item["documentation"] = {{"kind", "markdown"}, {"value", doc}};
    return item;
}

bool startsWithIgnoringCase(std::string_view text, std::string_view prefix) {
    if (prefix.size() > text.size()) return false;
    for (size_t i = 0; i < prefix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(text[i])) != std::tolower(static_cast<unsigned char>(prefix[i])))
            return false;
    return true;
}

// Requests are answered on the reading thread from the document's current text (its parse, the
// registries), never from a check: checks run on a thread of their own (the checker), newest text
// first, so a hover or a completion never waits for one (docs/editors.md). One mutex guards the
// documents, the checker's queue and the output, so whole messages go out one at a time.
class Server {
public:
    Server(const Inbox& inbox, std::ostream& out, std::ostream& log)
        : inbox_(inbox), out_(out), log_(log), checker_([this] { checkLoop(); }) {}

    // Stops the checker after the check it is in (its result is not published).
    ~Server() {
        {
            const std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        work_.notify_one();
        checker_.join();
    }

    // Handles one message; false once `exit` has arrived.
    bool handle(const json& message) {
        const std::lock_guard lock(mutex_);
        if (!message.is_object() || !message.contains("method") || !message["method"].is_string()) {
            // A response to a request of ours (we send none) is ignored; anything else is invalid.
            if (!(message.is_object() && message.contains("id") && (message.contains("result") || message.contains("error"))))
                sendError(message.is_object() && message.contains("id") ? message["id"] : json(nullptr), kInvalidRequest,
                          "a request needs a string 'method'");
            return true;
        }
        const std::string method = message["method"];
        const json params = message.value("params", json::object());
        if (message.contains("id")) {
            const json& id = message["id"];
            try {
                request(id, method, params);
            } catch (const json::exception& error) {
                sendError(id, kInvalidParams, fmt::format("{}: bad params: {}", method, error.what()));
            } catch (const std::exception& error) {
                sendError(id, kInternalError, fmt::format("{}: {}", method, error.what()));
            }
            return true;
        }
        if (method == "exit") return false;
        try {
            notification(method, params);
        } catch (const std::exception& error) {
            log_ << "voxc lsp: " << method << ": " << error.what() << "\n";
        }
        return true;
    }

    int exitCode() const { return shutdown_ ? 0 : 1; }

    void malformed(const std::string& why) {
        const std::lock_guard lock(mutex_);
        log_ << "voxc lsp: " << why << "\n";
        sendError(nullptr, kParseError, why);
    }

private:
    struct Document {
        std::string text;
        uint64_t generation = 0;         // its text's number (Server::generations_): checks publish the newest only
        std::set<std::string> otherUris; // rule files this document last published diagnostics to
    };

    void send(const json& message) { writeMessage(out_, dump(message)); }

    void sendResult(const json& id, json result) {
        send({{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}});
    }

    void sendError(const json& id, int code, const std::string& message) {
        send({{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}});
    }

    void notify(const char* method, json params) {
        send({{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
    }

    void request(const json& id, const std::string& method, const json& params) {
        if (shutdown_) return sendError(id, kInvalidRequest, "the server is shut down; only 'exit' is accepted");
        if (method == "initialize") {
            initialized_ = true;
            return sendResult(id, {{"capabilities",
                                    {{"positionEncoding", "utf-16"},
                                     {"textDocumentSync", {{"openClose", true}, {"change", 1}, {"save", true}}},
                                     {"hoverProvider", true},
                                     {"definitionProvider", true},
                                     {"completionProvider", {{"resolveProvider", false}}}}},
                                   {"serverInfo", {{"name", "voxc"}, {"version", "0.1.0"}}}});
        }
        if (!initialized_) return sendError(id, kServerNotInitialized, "initialize first");
        if (method == "shutdown") {
            shutdown_ = true;
            return sendResult(id, nullptr);
        }
        if (method == "textDocument/hover") return sendResult(id, hover(params));
        if (method == "textDocument/completion") return sendResult(id, completion(params));
        if (method == "textDocument/definition") return sendResult(id, definition(params));
        sendError(id, kMethodNotFound, "voxc lsp does not handle " + method);
    }

    void notification(const std::string& method, const json& params) {
        if (!initialized_ || shutdown_) return;
        if (method == "textDocument/didOpen") {
            const json& document = params.at("textDocument");
            const std::string uri = document.at("uri");
            Document& opened = documents_[uri];
            opened.text = document.at("text");
            opened.generation = ++generations_;
            publish(uri);
        } else if (method == "textDocument/didChange") {
            const std::string uri = params.at("textDocument").at("uri");
            const auto found = documents_.find(uri);
            if (found == documents_.end()) return;
            for (const json& change : params.at("contentChanges")) applyChange(found->second.text, change);
            found->second.generation = ++generations_;
            // A newer edit already waiting will be checked instead: typing stays ahead of slow checks.
            if (!inbox_.changeWaiting(uri)) publish(uri);
        } else if (method == "textDocument/didSave") {
            // A saved rule file changes what the .vox files that import it say.
            for (const auto& [uri, document] : documents_) publish(uri);
        } else if (method == "textDocument/didClose") {
            const std::string uri = params.at("textDocument").at("uri");
            const auto found = documents_.find(uri);
            if (found == documents_.end()) return;
            std::set<std::string> uris = found->second.otherUris;
            uris.insert(uri);
            documents_.erase(found);
            pending_.erase(uri);
            for (const std::string& cleared : uris)
                notify("textDocument/publishDiagnostics", {{"uri", cleared}, {"diagnostics", json::array()}});
        }
    }

    static void applyChange(std::string& text, const json& change) {
        const std::string replacement = change.at("text");
        if (!change.contains("range")) {
            text = replacement;
            return;
        }
        const json& range = change["range"];
        const auto position = [](const json& p) { return Position{p.at("line"), p.at("character")}; };
        const size_t start = byteOffset(text, position(range.at("start")));
        const size_t end = std::max(start, byteOffset(text, position(range.at("end"))));
        text.replace(start, end - start, replacement);
    }

    // Queues the document for the checker, replacing an older text of it still waiting.
    void publish(const std::string& uri) {
        const Document& document = documents_.at(uri);
        pending_[uri] = {document.text, document.generation};
        work_.notify_one();
    }

    struct Job {
        std::string text;
        uint64_t generation = 0;
    };

    // The checker's thread: checks each queued text as `voxc check` would check the file and
    // publishes what it says, per file (those located in a rule file it imports go to that file's
    // URI), unless the document changed or closed meanwhile: then a newer check is queued, or
    // nothing is wanted.
    void checkLoop() {
        std::unique_lock lock(mutex_);
        for (;;) {
            work_.wait(lock, [&] { return stopping_ || !pending_.empty(); });
            if (stopping_) return;
            const auto next = pending_.begin();
            const std::string uri = next->first;
            const Job job = std::move(next->second);
            pending_.erase(next);
            lock.unlock();
            const SourceFile source(uriToPath(uri), job.text);
            std::vector<Diagnostic> diagnostics;
            try {
                diagnostics = check(source);
            } catch (const std::exception& error) {
                diagnostics = {{Severity::Error, "", {}, fmt::format("voxc could not check this file: {}", error.what()), {}, nullptr}};
            }
            lock.lock();
            const auto document = documents_.find(uri);
            if (stopping_ || document == documents_.end() || document->second.generation != job.generation) continue;
            sendDiagnostics(uri, document->second, source, diagnostics);
        }
    }

    static std::vector<Diagnostic> check(const SourceFile& source) {
        const Limits limits;
        if (source.text().size() > size_t(limits.maxSourceBytes))
            return {{Severity::Error, "E0012", {},
                     fmt::format("the document is larger than the limit of {} bytes ({} MiB)", limits.maxSourceBytes,
                                 limits.maxSourceBytes >> 20),
                     {}, nullptr}};
        return checkSource(source, CheckOptions{}).diagnostics;
    }

    void sendDiagnostics(const std::string& uri, Document& document, const SourceFile& source,
                         const std::vector<Diagnostic>& diagnostics) {
        std::map<std::string, json> byUri{{uri, json::array()}};
        for (const Diagnostic& diagnostic : diagnostics) {
            const SourceFile& file = diagnostic.file ? *diagnostic.file : source;
            const std::string target = diagnostic.file ? pathToUri(diagnostic.file->path()) : uri;
            byUri.try_emplace(target, json::array()).first->second.push_back(diagnosticJson(diagnostic, file, target));
        }
        for (const std::string& old : document.otherUris) byUri.try_emplace(old, json::array());
        document.otherUris.clear();
        for (auto& [target, list] : byUri) {
            if (target != uri && !list.empty()) document.otherUris.insert(target);
            notify("textDocument/publishDiagnostics", {{"uri", target}, {"diagnostics", std::move(list)}});
        }
    }

    static json diagnosticJson(const Diagnostic& diagnostic, const SourceFile& file, const std::string& uri) {
        const int severity = diagnostic.severity == Severity::Error ? 1 : diagnostic.severity == Severity::Warning ? 2 : 3;
        json out{{"range", rangeJson(diagnostic.loc, file)}, {"severity", severity}, {"source", "voxc"},
                 {"message", diagnostic.message}};
        if (!diagnostic.code.empty()) out["code"] = diagnostic.code;
        json related = json::array();
        for (const DiagnosticNote& note : diagnostic.notes)
            related.push_back({{"location", {{"uri", uri}, {"range", rangeJson(note.loc, file)}}}, {"message", note.message}});
        if (!related.empty()) out["relatedInformation"] = std::move(related);
        return out;
    }

    // The document, its parse, and the word and place at an LSP position.
    struct Context {
        std::string text;
        ast::File file;
        Place place{0, 0};
        std::string word;   // the identifier around the position
        std::string prefix; // its part before the position
    };

    std::optional<Context> contextAt(const json& params) {
        const std::string uri = params.at("textDocument").at("uri");
        const auto found = documents_.find(uri);
        if (found == documents_.end()) return std::nullopt;
        Context context;
        context.text = found->second.text;
        if (context.text.size() > size_t(Limits{}.maxSourceBytes)) return std::nullopt;
        const Position position{params.at("position").at("line"), params.at("position").at("character")};
        const size_t offset = byteOffset(context.text, position);
        size_t begin = offset, end = offset;
        while (begin > 0 && isWordCharacter(context.text[begin - 1])) --begin;
        while (end < context.text.size() && isWordCharacter(context.text[end])) ++end;
        context.word = context.text.substr(begin, end - begin);
        context.prefix = context.text.substr(begin, offset - begin);
        const std::string_view line = lineOf(context.text, position.line);
        context.place = {position.line + 1, characterColumn(line, position.character) + 1};
        Diagnostics ignored; // the checker reports them; help works on whatever parsed
        context.file = parse(SourceFile(uriToPath(uri), context.text), ignored);
        return context;
    }

    json hover(const json& params) {
        const std::optional<Context> context = contextAt(params);
        if (!context || context->word.empty()) return nullptr;
        std::string markdown;
        const BlockAt at = blockAt(context->file, context->place);
        if (at.key) {
            for (const WordHelp& key : registryKeys(at.block->kind))
                if (key.name == at.key->key) markdown = fmt::format("**{}** ({})\n\n{}", key.name, key.detail, key.documentation);
            if (markdown.empty())
                markdown = fmt::format("**{}**: a key of the `{}` block (docs/language.md)", at.key->key, at.block->kind);
        } else if (const std::optional<WordHelp> builtin = findBuiltin(context->word)) {
            markdown = fmt::format("**{}** ({})\n\n{}", builtin->name, builtin->detail, builtin->documentation);
        } else {
            const SourceFile source("", context->text);
            for (const Declared& name : declaredNames(context->file))
                if (name.name == context->word)
                    markdown = fmt::format("**{}** ({}), line {}\n```\n{}\n```", name.name, name.detail, name.loc.line,
                                           source.line(name.loc.line));
        }
        if (markdown.empty()) return nullptr;
        return {{"contents", {{"kind", "markdown"}, {"value", markdown}}}};
    }

    // Where the file declares the name at the position (a constant, function, field, feature or
    // labelled block), from the document's current text.
    json definition(const json& params) {
        const std::optional<Context> context = contextAt(params);
        if (!context || context->word.empty()) return nullptr;
        const std::string uri = params.at("textDocument").at("uri");
        const SourceFile source(uriToPath(uri), context->text);
        for (const Declared& name : declaredNames(context->file))
            if (name.name == context->word) return {{"uri", uri}, {"range", rangeJson(name.loc, source)}};
        return nullptr;
    }

    json completion(const json& params) {
        json items = json::array();
        const std::optional<Context> context = contextAt(params);
        if (!context) return {{"isIncomplete", false}, {"items", items}};
        const auto add = [&](const std::string& label, WordKind kind, const std::string& detail, const std::string& doc,
                             const char* group) {
            if (startsWithIgnoringCase(label, context->prefix)) items.push_back(completionItem(label, kind, detail, doc, group));
        };
        // Keys of the enclosing block first, then the file's names, then the builtins.
        if (const BlockAt at = blockAt(context->file, context->place); at.block)
            for (const WordHelp& key : registryKeys(at.block->kind))
                add(key.name, key.kind, key.detail, key.documentation, "0");
        std::set<std::string> seen;
        for (const Declared& name : declaredNames(context->file))
            if (seen.insert(name.name).second)
                add(name.name, name.kind, name.detail, "", "1");
        for (const WordHelp& word : builtinWords())
            if (seen.insert(word.name).second) add(word.name, word.kind, word.detail, word.documentation, "2");
        return {{"isIncomplete", false}, {"items", std::move(items)}};
    }

    const Inbox& inbox_;
    std::ostream& out_;
    std::ostream& log_;
    std::mutex mutex_;
    std::condition_variable work_;           // the checker waits on it for pending_ or stopping_
    std::map<std::string, Document> documents_;
    std::map<std::string, Job> pending_;     // texts waiting for the checker, by URI
    uint64_t generations_ = 0;               // texts seen, over all documents (closed and reopened ones too)
    bool stopping_ = false;
    bool initialized_ = false;
    bool shutdown_ = false;
    std::thread checker_;                    // last: started once everything it reads exists
};

} // namespace

int serve(std::istream& in, std::ostream& out, std::ostream& log) {
    Inbox inbox(in);
    Server server(inbox, out, log);
    for (;;) {
        const Incoming incoming = inbox.next();
        switch (incoming.kind) {
        case Incoming::Kind::End: return 1; // the input ended without `exit`
        case Incoming::Kind::Malformed: server.malformed(incoming.error); break;
        case Incoming::Kind::Message:
            if (!server.handle(incoming.message)) return server.exitCode();
            break;
        }
    }
}

} // namespace voxc::lsp
