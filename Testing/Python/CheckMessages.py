"""Checks the messages a ParaView run printed (its output, as run-with-x.sh keeps it in
$SHRINKWRAP_X_LOG): CheckMessages.py <log> [--once <text>] [--never <text>] ...
Fails on any warning or error line, on a --once text that is not on exactly one line, and on a
--never text that is on any."""
import sys

log, rules = sys.argv[1], sys.argv[2:]
lines = open(log, errors="replace").read().splitlines()
failed = 0


def report(ok, what):
    global failed
    failed += not ok
    print("%s %s" % ("ok  " if ok else "FAIL", what))


alarms = [line for line in lines if "WARN|" in line or "ERR|" in line or "Warning:" in line or "Error:" in line]
report(not alarms, "no warning or error (%s)" % ("; ".join(alarms)[:2000] or "none"))
for kind, text in zip(rules[0::2], rules[1::2]):
    count = sum(text in line for line in lines)
    if kind == "--once":
        report(count == 1, "'%s' said once (%d times)" % (text, count))
    elif kind == "--never":
        report(count == 0, "'%s' never said (%d times)" % (text, count))
    else:
        report(False, "unknown rule %s" % kind)
print("%d failed" % failed)
sys.exit(1 if failed else 0)
