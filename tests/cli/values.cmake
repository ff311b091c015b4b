# Tests that check the values a command writes, not only that it ran.
