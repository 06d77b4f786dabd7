#!/usr/bin/env bash
# Prints the path of a Python interpreter that imports matplotlib and numpy. The python3 on
# PATH may be a separate interpreter without them, so Debian's /usr/bin/python3 comes first.
for py in /usr/bin/python3 "$(command -v python3 || true)" /usr/local/bin/python3; do
  [ -n "$py" ] && [ -x "$py" ] || continue
  if "$py" -c "import matplotlib, numpy" 2>/dev/null; then echo "$py"; exit 0; fi
done
echo "sphv: error: no Python interpreter imports matplotlib and numpy; install the Debian packages python3-matplotlib python3-numpy (scripts/install-deps.sh does)" >&2
exit 1
