# SPDX-License-Identifier: BSD-3-Clause
"""The tools for the user's mROS v1 library: the fit flow (:mod:`.fit_flow`:
an app's or an export dir's types against the library's settings) and its
report (:mod:`.report`), the PC target (:mod:`.pc_target`) and the opt-in
patch series (:mod:`.patches`)."""
