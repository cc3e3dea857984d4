#include "LspCases.h"

#include "voxc/core/Errors.h"
#include "voxc/lsp/Server.h"

#include <algorithm>
#include <benchmark/benchmark.h>
#include <chrono>
#include <ext/stdio_filebuf.h>
#include <fmt/format.h>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace voxc::bench {

namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A server on a thread of its own, spoken to through two pipes. The server's reading thread is
// detached and may outlive serve(), so the server's ends of the pipes live as long as the process.
class LspSession {
public:
    LspSession() {
        int toServer[2], fromServer[2];
        if (pipe(toServer) != 0 || pipe(fromServer) != 0) throw UserError("lsp_latency: cannot make pipes");
        write_ = toServer[1];
        read_ = fromServer[0];
        static std::vector<std::unique_ptr<std::iostream>> kept; // the server's streams, for the process's life
        static std::vector<std::unique_ptr<__gnu_cxx::stdio_filebuf<char>>> buffers;
        buffers.push_back(std::make_unique<__gnu_cxx::stdio_filebuf<char>>(toServer[0], std::ios::in));
        kept.push_back(std::make_unique<std::iostream>(buffers.back().get()));
        std::istream& in = *kept.back();
        buffers.push_back(std::make_unique<__gnu_cxx::stdio_filebuf<char>>(fromServer[1], std::ios::out));
        kept.push_back(std::make_unique<std::iostream>(buffers.back().get()));
        std::ostream& out = *kept.back();
        server_ = std::thread([&in, &out] {
            std::ostringstream log;
            lsp::serve(in, out, log);
            out.flush();
        });
    }

    ~LspSession() {
        request("shutdown", json::object());
        send({{"jsonrpc", "2.0"}, {"method", "exit"}});
        server_.join();
        close(write_);
        close(read_);
    }

    void send(const json& message) {
        const std::string body = message.dump();
        const std::string framed = fmt::format("Content-Length: {}\r\n\r\n{}", body.size(), body);
        for (size_t done = 0; done < framed.size();) {
            const ssize_t n = ::write(write_, framed.data() + done, framed.size() - done);
            if (n <= 0) throw UserError("lsp_latency: the server stopped reading");
            done += size_t(n);
        }
    }

    json request(const std::string& method, json params) {
        const int id = nextId_++;
        send({{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}});
        for (;;) {
            json message = read();
            if (message.contains("id") && message["id"] == id) return message;
            notifications_.push_back(std::move(message));
        }
    }

    // The next publishDiagnostics for `uri`, reading on as needed.
    json diagnostics(const std::string& uri) {
        for (;;) {
            for (auto it = notifications_.begin(); it != notifications_.end(); ++it)
                if ((*it)["params"]["uri"] == uri) {
                    json found = std::move((*it)["params"]["diagnostics"]);
                    notifications_.erase(it);
                    return found;
                }
            notifications_.push_back(read());
        }
    }

private:
    json read() {
        std::string header;
        while (!header.ends_with("\r\n\r\n")) header += byte();
        const size_t at = header.find("Content-Length: ");
        if (at == std::string::npos) throw UserError("lsp_latency: a message without Content-Length");
        const size_t length = std::stoul(header.substr(at + 16));
        std::string body;
        while (body.size() < length) body += byte();
        return json::parse(body);
    }

    char byte() {
        char c = 0;
        if (::read(read_, &c, 1) != 1) throw UserError("lsp_latency: the server closed its output");
        return c;
    }

    int write_ = -1, read_ = -1;
    int nextId_ = 1;
    std::vector<json> notifications_;
    std::thread server_;
};

std::string readExample(const std::string& relative) {
    const std::string path = std::string(VOXC_SOURCE_DIR) + "/" + relative;
    std::ifstream in(path);
    if (!in) throw UserError("lsp_latency: cannot read " + path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

void registerLspLatency(JsonReporter& reporter) {
    const std::string name = "lsp_latency";
    benchmark::RegisterBenchmark(name.c_str(), [](benchmark::State& state) {
        const std::string path = std::string(VOXC_SOURCE_DIR) + "/examples/valley.vox";
        const std::string uri = "file://" + path, text = readExample("examples/valley.vox");
        LspSession session;
        session.request("initialize", {{"capabilities", json::object()}});
        session.send({{"jsonrpc", "2.0"}, {"method", "initialized"}, {"params", json::object()}});
        json document = {{"uri", uri}, {"languageId", "vox"}, {"version", 1}, {"text", text}};
        session.send({{"jsonrpc", "2.0"}, {"method", "textDocument/didOpen"}, {"params", {{"textDocument", document}}}});
        if (!session.diagnostics(uri).empty()) throw UserError("lsp_latency: examples/valley.vox has diagnostics");
        int version = 1;
        double diagnosticsMs = 0.0;
        for (auto _ : state) {
            // An edit that leaves the file valid: a comment line, then `f` typed on a new line.
            const std::string edited = text + fmt::format("// edit {}\n", ++version);
            const auto start = Clock::now();
            json change = json::object();
            change["textDocument"] = {{"uri", uri}, {"version", version}};
            change["contentChanges"] = json::array({json{{"text", edited}}});
            session.send({{"jsonrpc", "2.0"}, {"method", "textDocument/didChange"}, {"params", change}});
            json at = json::object();
            at["textDocument"] = {{"uri", uri}};
            at["position"] = {{"line", std::count(edited.begin(), edited.end(), '\n')}, {"character", 0}};
            const json completion = session.request("textDocument/completion", at);
            const double ms = msSince(start);
            state.SetIterationTime(ms / 1000.0);
            if (!completion.contains("result") || completion["result"]["items"].empty())
                throw UserError("lsp_latency: completion gave no items");
            if (!session.diagnostics(uri).empty()) throw UserError("lsp_latency: the edit gave diagnostics");
            diagnosticsMs += msSince(start);
        }
        state.counters["diagnostics_ms"] = benchmark::Counter(diagnosticsMs, benchmark::Counter::kAvgIterations);
    })->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(20);
    reporter.describe(name + "/iterations:20/manual_time", {"lsp_latency", 20, "host", "voxc lsp, valley.vox"});
}

} // namespace voxc::bench
