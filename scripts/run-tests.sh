#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The README's test command: installs what is needed (scripts/setup.sh), then
# runs the whole test suite with Debian's python3, the one that has genmsg.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh" --tests
cd "$here"
exec /usr/bin/python3 -m pytest -p no:cacheprovider tests "$@"
