"""What a run leaves behind: saved states, provenance records and run logs."""
