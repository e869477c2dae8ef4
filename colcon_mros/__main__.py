# SPDX-License-Identifier: BSD-3-Clause
"""Entry point of ``python3 -m colcon_mros``: the ``genmros`` command."""

import sys

from colcon_mros.cli import main

sys.exit(main())
