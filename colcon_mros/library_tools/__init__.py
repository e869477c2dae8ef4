# SPDX-License-Identifier: BSD-3-Clause
"""Tools that work on the user's mROS library, not only on its messages.

What every mROS line's tools share is here (:mod:`.patch_series`: a patch
series applied to, checked on and taken out of a checkout); each line has
its own subpackage (:mod:`.mros_v1`: the fit flow and report, the PC
target, the patch series). They use the export and the integrations.
"""
