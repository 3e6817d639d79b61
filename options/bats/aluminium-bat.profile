# Illustrative hollow aluminium bat of our own making (not a measured bat): 84 cm (33 in),
# 2 5/8 in (66.7 mm) barrel, 25.4 mm handle, a thick-walled knob. Rows: x from the knob end
# (m), outer diameter D (m), inner diameter d (m); diameters linear between rows. With 7046
# aluminium (E = 72 GPa, rho = 2810 kg/m^3) it weighs 0.88 kg, centre of mass 49 cm from the
# knob: a plausible BBCOR-type bat (walls 2.5 mm in the barrel, 3 mm in the handle).
0.000  0.0460  0.0340
0.012  0.0460  0.0340
0.016  0.0254  0.0194
0.200  0.0254  0.0194
0.300  0.0300  0.0244
0.450  0.0520  0.0470
0.530  0.0667  0.0617
0.840  0.0667  0.0617
