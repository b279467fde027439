#!/usr/bin/env python3
"""Latency of `shaderport lsp`: the time from a didChange (one character edited) to
its publishDiagnostics, for a 60-line and a 2,000-line ShaderToy pass that compile. Prints p50 and p95 over --rounds edits of each. Run on demand:

  bench/lsp_latency.py BUILD/shaderport [--rounds 40]
"""
import argparse
import json
import statistics
import subprocess
import sys
import time



class Client:
    def __init__(self, binary):
        self.process = subprocess.Popen([binary, "lsp"], stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE)
        self.send({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}})
        self.receive()

    def send(self, message):
        body = json.dumps(message).encode()
        self.process.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.process.stdin.flush()

    def receive(self):
        length = 0
        while True:
            line = self.process.stdout.readline().strip()
            if not line:
                break
            if line.lower().startswith(b"content-length:"):
                length = int(line.split(b":")[1])
        return json.loads(self.process.stdout.read(length))

    def published(self, version):
        """Reads until the diagnostics of `version` (status and log messages come too)."""
        while True:
            message = self.receive()
            if message.get("method") == "textDocument/publishDiagnostics" and \
                    message["params"].get("version") == version:
                return message


def shader(lines_wanted):
    """A valid ShaderToy pass of about `lines_wanted` lines: distance functions in the
    style of real passes (loops, vectors, calls), one after another."""
    text = ""
    count = 0
    while text.count("\n") < lines_wanted - 6:
        text += ("float sd%d(vec3 p, float r) {\n"
                 "    vec3 q = abs(p) - vec3(r * 0.5);\n"
                 "    float d = length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);\n"
                 "    for (int i = 0; i < 4; i++) {\n"
                 "        p = abs(p) - vec3(0.25 * float(i));\n"
                 "        d = min(d, length(p) - r * %d.0 / 100.0);\n"
                 "    }\n"
                 "    return d + sin(iTime + float(%d)) * 0.01;\n"
                 "}\n") % (count, count % 97 + 1, count)
        count += 1
    return text + ("void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                   "    vec3 p = vec3(fragCoord / iResolution.xy, 1.0);\n"
                   "    fragColor = vec4(vec3(sd0(p, 0.5) + sd%d(p, 0.25)), 1.0);\n"
                   "}\n") % (count - 1)


def measure(client, name, text, rounds):
    uri = "file:///tmp/bench-%s.glsl" % name
    client.send({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {
        "uri": uri, "languageId": "glsl", "version": 1, "text": text}}})
    client.published(1)
    times = []
    last = text.count("\n") - 1
    for version in range(2, rounds + 2):
        edit = {"range": {"start": {"line": last, "character": 0}, "end": {"line": last, "character": 1}},
                "text": "}" if version % 2 else "}"}
        start = time.perf_counter()
        client.send({"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {
            "textDocument": {"uri": uri, "version": version}, "contentChanges": [edit]}})
        client.published(version)
        times.append((time.perf_counter() - start) * 1000)
    times.sort()
    p95 = times[min(len(times) - 1, int(len(times) * 0.95))]
    print("%-6s %5d lines: p50 %.1f ms, p95 %.1f ms (%d edits)" %
          (name, text.count("\n"), statistics.median(times), p95, rounds))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("--rounds", type=int, default=40)
    args = parser.parse_args()
    client = Client(args.binary)
    measure(client, "small", shader(60), args.rounds)
    measure(client, "large", shader(2000), args.rounds)


main()
