"""esper processors (systems) that ship with kge; see :mod:`kge.schedule` for the order."""
