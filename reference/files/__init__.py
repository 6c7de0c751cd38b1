"""Files the user names: :mod:`.outputs` checks and writes them (an unwritable path is bad input)."""
