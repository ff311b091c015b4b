# One run's outputs are written together or not at all.
