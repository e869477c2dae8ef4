# SPDX-License-Identifier: BSD-3-Clause
"""Tools on the user's mros2 checkout: its opt-in patch series."""
