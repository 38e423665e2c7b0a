"""Body model backends (``massspring``, ``fem``, ``hybrid``), one subpackage each.  Each reads
``core.protocols.Actuation`` and fills ``Observation``; none imports a controller.
``bench_myriapoda.catalog`` lists them by name."""
