"""Tools on the user's mros2 checkout: its opt-in patch series."""
