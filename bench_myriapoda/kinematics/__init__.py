"""Kinematics shared by bodies and controllers: leg FK/IK (paper Sec. 4.2, App. B) and small
rotation helpers.  Neither ``bodies/`` nor ``controllers/`` is imported from here, so both may use it."""
