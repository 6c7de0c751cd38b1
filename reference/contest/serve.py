"""Serving the contest application on an address: in the foreground (``topomark contest serve``) or in a thread.

The listening socket is opened here, before the server starts, so a port already in use or a host that is not an
address of the local host is one :class:`~topomark.spec.errors.InvalidInput` (exit 2), and port 0 takes a free port
whose number the caller prints.  The server is uvicorn's: in the foreground it handles Ctrl-C itself (it stops
taking requests, finishes those it has, closes) and then hands the interrupt on, so the command ends as every
topomark command does after Ctrl-C.

Only a loopback host (``127.0.0.1``, ``::1``, ``localhost``) is served unless ``allow_remote``: the server runs
whatever plans it is sent and keeps the sessions of whoever calls it, with no authentication, so offering it to a
network is a decision to take explicitly (``--allow-remote``).
"""

from __future__ import annotations

import contextlib
import ipaddress
import socket
import threading
import time
from typing import Any, Iterator

from topomark.spec.errors import InvalidInput, TopomarkFault, clip, require_input

__all__ = ["check_host", "listen", "serve", "serving", "url_of", "LOOPBACK_NAMES"]

LOOPBACK_NAMES = ("localhost",)


def check_host(host: str, allow_remote: bool) -> None:
    """Refuse (InvalidInput) a host that is not a loopback address, unless ``allow_remote``.

    >>> check_host("127.0.0.1", False); check_host("::1", False)
    >>> check_host("0.0.0.0", False)
    Traceback (most recent call last):
    ...
    topomark.spec.errors.InvalidInput: --host 0.0.0.0 is not a loopback address: the server would take plans and guesses from other machines, unauthenticated; give --allow-remote to serve there
    """
    if allow_remote or host in LOOPBACK_NAMES:
        return
    try:
        loopback = ipaddress.ip_address(host).is_loopback
    except ValueError:
        loopback = False
    require_input(loopback, f"--host {clip(host, 80)} is not a loopback address: the server would take plans and "
                  "guesses from other machines, unauthenticated; give --allow-remote to serve there")


def listen(host: str, port: int) -> socket.socket:
    """A socket listening on ``host``:``port`` (0: a free port)."""
    require_input(0 <= port <= 65535, f"--port {port} is not a port (0 to 65535; 0 takes a free one)")
    try:
        infos = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE)
    except OSError as e:
        raise InvalidInput(f"--host {clip(host, 80)}: not an address of the local host ({e.strerror or e})") from None
    family, kind, proto, _, address = infos[0]
    sock = socket.socket(family, kind, proto)
    try:
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind(address)
        sock.listen(128)
    except OSError as e:
        sock.close()
        raise InvalidInput(f"cannot listen on {clip(host, 80)} port {port}: {e.strerror or e}") from None
    return sock


def url_of(sock: socket.socket) -> str:
    """``http://HOST:PORT`` of a listening socket."""
    host, port = sock.getsockname()[:2]
    return f"http://[{host}]:{port}" if ":" in host else f"http://{host}:{port}"


def _server(app: Any) -> Any:
    import uvicorn  # here: only a command that serves pays for it

    config = uvicorn.Config(app, log_level="warning", access_log=False, lifespan="off", timeout_graceful_shutdown=5)
    return uvicorn.Server(config)


def serve(app: Any, sock: socket.socket) -> None:
    """Serve ``app`` on ``sock`` until Ctrl-C (then the interrupt is raised again, as a KeyboardInterrupt)."""
    _server(app).run(sockets=[sock])


@contextlib.contextmanager
def serving(app: Any, host: str = "127.0.0.1", port: int = 0, timeout: float = 10.0) -> Iterator[str]:
    """Serve ``app`` in a background thread for the ``with`` block; yields the server's URL."""
    sock = listen(host, port)
    server = _server(app)
    thread = threading.Thread(target=server.run, kwargs={"sockets": [sock]}, daemon=True, name="contest-server")
    thread.start()
    deadline = time.monotonic() + timeout
    while not server.started:
        if not thread.is_alive() or time.monotonic() > deadline:
            sock.close()
            raise TopomarkFault("the contest server did not start")
        time.sleep(0.01)
    try:
        yield url_of(sock)
    finally:
        server.should_exit = True
        thread.join(timeout)
        sock.close()
