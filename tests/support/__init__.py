# SPDX-License-Identifier: BSD-3-Clause
"""What the test modules share: this checkout's paths, genmros run from it,
the user's checkouts, installs of the checkout, and builders of the programs
and files several tests use. The tests import it as ``support`` (pytest puts
tests/ on the path, beside conftest.py); bench/ and evaluation/ share
testing/ instead."""
