"""Running Exudyn's solver on a scene with bearings: ``simulate`` and ``run_solver``."""
