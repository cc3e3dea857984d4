"""A minimal LSP client over a `voxc lsp` process's pipes, for the tests in this folder."""
import json
import subprocess
import sys
import urllib.parse

counts = {"passed": 0, "failed": 0}


def check(name, condition, detail=""):
    counts["passed" if condition else "failed"] += 1
    print(("ok   " if condition else "FAIL ") + name + (": " + str(detail)[:2000] if detail and not condition else ""))


def finish():
    """Prints "N passed, N failed" and exits non-zero on any failure."""
    print("%d passed, %d failed" % (counts["passed"], counts["failed"]))
    sys.exit(1 if counts["failed"] else 0)


def uri(path):
    return "file://" + urllib.parse.quote(path)


class Client:
    def __init__(self, voxc):
        self.process = subprocess.Popen([voxc, "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        self.next_id = 1
        self.notifications = []

    def send_raw(self, data):
        self.process.stdin.write(data)
        self.process.stdin.flush()

    def send(self, message):
        body = json.dumps(message).encode()
        self.send_raw(b"Content-Length: %d\r\n\r\n" % len(body) + body)

    def read(self):
        length = None
        while True:
            line = self.process.stdout.readline()
            if not line:
                raise EOFError("the server closed its output")
            line = line.strip()
            if not line:
                break
            key, _, value = line.partition(b":")
            if key.lower() == b"content-length":
                length = int(value)
        return json.loads(self.process.stdout.read(length))

    def request(self, method, params=None):
        request_id = self.next_id
        self.next_id += 1
        self.send({"jsonrpc": "2.0", "id": request_id, "method": method, "params": params or {}})
        return self.response(request_id)

    def response(self, request_id):
        while True:
            message = self.read()
            if "method" in message:
                self.notifications.append(message)
            elif message.get("id") == request_id:
                return message

    def notify(self, method, params):
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def diagnostics_for(self, document_uri):
        """The next publishDiagnostics for `document_uri` (reading on as needed)."""
        while True:
            for i, message in enumerate(self.notifications):
                if message["method"] == "textDocument/publishDiagnostics" and message["params"]["uri"] == document_uri:
                    del self.notifications[i]
                    return message["params"]["diagnostics"]
            message = self.read()
            if "method" in message:
                self.notifications.append(message)
