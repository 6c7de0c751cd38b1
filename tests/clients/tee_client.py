#!/usr/bin/env python3
"""Runs a program (argv[2:], default reference/oracle/examples/client.py) and writes the whole session to the file
argv[1]: "> " lines are what topomark sent, "< " lines what the program sent (for doc and schema tests)."""
import subprocess
import sys
import threading
from pathlib import Path

CLIENT = Path(__file__).resolve().parents[2] / "reference" / "oracle" / "examples" / "client.py"
log = open(sys.argv[1], "w")
child = subprocess.Popen(sys.argv[2:] or [sys.executable, str(CLIENT)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
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
