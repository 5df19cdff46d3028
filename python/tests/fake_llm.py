"""A slow OpenAI-compatible completions server on 127.0.0.1 for the
progress tests: every answer is the same goal statement, with
log-probabilities, after a delay."""
import http.server
import json
import threading
import time

STATEMENT = " The goal is that the object is in the garbage."


class _Handler(http.server.BaseHTTPRequestHandler):
    delay = 0.3

    def do_POST(self):  # noqa: N802 (http.server's name)
        length = int(self.headers.get("Content-Length", 0))
        self.rfile.read(length)
        self.answer()

    def answer(self):
        """The one goal statement, with log-probabilities, after the delay."""
        time.sleep(self.delay)
        tokens = [" " + word for word in STATEMENT.split()]
        body = json.dumps({
            "choices": [{"text": "".join(tokens), "finish_reason": "stop",
                         "logprobs": {"tokens": tokens, "token_logprobs": [-0.1] * len(tokens),
                                      "top_logprobs": [{t: -0.1} for t in tokens]}}],
            "usage": {"prompt_tokens": 10, "completion_tokens": len(tokens)},
        }).encode()
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def log_message(self, format, *args):  # noqa: A002 (http.server's name)
        pass


class SlowLlmServer:
    def __init__(self, delay=0.3):
        handler = type("Handler", (_Handler,), {"delay": delay})
        self.server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        self.thread = threading.Thread(target=self.server.serve_forever, daemon=True)

    @property
    def url(self):
        return "http://127.0.0.1:%d/v1" % self.server.server_address[1]

    def __enter__(self):
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.server.shutdown()
        self.server.server_close()


class RecordingLlmServer(SlowLlmServer):
    """The same server, quick, keeping each request as it came: its JSON
    body and its Authorization header, so that a test can see what the
    options sent."""

    def __init__(self, delay=0.0):
        requests = self.requests = []

        class Handler(_Handler):
            def do_POST(self):  # noqa: N802 (http.server's name)
                length = int(self.headers.get("Content-Length", 0))
                body = self.rfile.read(length)
                requests.append({"body": json.loads(body or b"{}"),
                                 "authorization": self.headers.get("Authorization")})
                self.answer()

        Handler.delay = delay
        self.server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self.thread = threading.Thread(target=self.server.serve_forever, daemon=True)
