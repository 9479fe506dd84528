"""NC programs: ``program`` reads the constructs the N rules check (``#MACHINE DATA``, G98/G99)."""
