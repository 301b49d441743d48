"""What researchers look at: the figures."""
