"""Controllers (gaits): Miller's muscle waves (``muscle_waves``) and the myriapod leg controller
(``myriapod``).  Each reads ``core.protocols.Observation`` and writes ``Actuation``; none imports a
body.  ``bench_myriapoda.catalog`` lists them by gait name."""
