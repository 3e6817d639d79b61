# A solid wood cylinder of 3 in (76.2 mm) diameter, 30 cm long: Nathan et al. 2012's target
# (a 3-inch wood cylinder fixed to a wall), clamped at both ends by scripts/study_oblique.sh.
# Rows: x (m), outer diameter D (m).
0.00 0.0762
0.30 0.0762
