"""The myriapod leg controller of Fang, Jiang & Terzopoulos (2013), Sec. 4:
a Targeter per rigid segment (``targeter``) and a Switcher per leg (``switcher``), sequenced by
``controller.MyriapodController``.  Leg kinematics and IK live in ``bench_myriapoda.kinematics.legs``."""
