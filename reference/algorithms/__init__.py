"""The algorithm registry: :mod:`.registry` lists every algorithm, built from :mod:`.registrations`
with :mod:`.algorithm_spec`'s specs and :mod:`.bounds`'s exact bounds."""
