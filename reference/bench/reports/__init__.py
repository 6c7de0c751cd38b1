"""The bench's reports: :mod:`.kit` (what every report shares) and one module per part of the thesis."""
