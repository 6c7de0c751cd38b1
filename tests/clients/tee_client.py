#!/usr/bin/env python3
"""Runs reference/oracle/examples/client.py and appends the whole session to the file argv[1] (for doc tests)."""
import subprocess
import sys
import threading
from pathlib import Path

CLIENT = Path(__file__).resolve().parents[2] / "reference" / "oracle" / "examples" / "client.py"
log = open(sys.argv[1], "w")
child = subprocess.Popen([sys.executable, str(CLIENT)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
lock = threading.Lock()


def downstream():
    for line in sys.stdin:
        with lock:
            log.write("> " + line)
            log.flush()
        child.stdin.write(line)
        child.stdin.flush()


threading.Thread(target=downstream, daemon=True).start()
for line in child.stdout:
    with lock:
        log.write("< " + line)
        log.flush()
    sys.stdout.write(line)
    sys.stdout.flush()
sys.exit(child.wait())
