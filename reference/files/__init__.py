"""Files the user names: :mod:`.outputs` checks and writes them (an unwritable path is bad input); :mod:`.overwrite`
says what happens to one that is already there."""
