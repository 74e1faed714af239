# bench.png: written by m3055 bench from bench.csv; run `gnuplot bench.gp` in this folder to
# redraw it (gnuplot -e "out='other.png'" bench.gp for another name).
if (!exists("out")) out = "bench.png"
set terminal pngcairo size 1200,720 enhanced font "DejaVu Sans,11"
set output out
set lmargin at screen 0.0833333
set rmargin at screen 0.975
set tmargin at screen 0.916667
set bmargin at screen 0.111111
set title "Run time against error, per way of rendering (512 x 320)" font ",15"
set key at graph 0.995, graph 0.99 right top box opaque reverse Left samplen 1.5 spacing 1.15 font ",10.5"
set border 3 lw 1.2
set logscale xy
set xrange [1:100]
set yrange [1e-09:0.1]
set format x "%g"
set ytics nomirror ("0" 2.51189e-09, "10^{-8}" 1e-8, "10^{-7}" 1e-7, "10^{-6}" 1e-6, "10^{-5}" 1e-5, "10^{-4}" 1e-4, "10^{-3}" 1e-3, "10^{-2}" 1e-2, "10^{-1}" 1e-1)
set mxtics 10
set xtics nomirror
set grid xtics ytics mxtics lc rgb "#dddddd" lw 1, lc rgb "#eeeeee" lw 1
set arrow from graph 0, first 5.01187e-09 to graph 1, first 5.01187e-09 nohead dt 2 lc rgb "#808080" back
set xlabel "time per frame at 512 x 320, ms (median, log scale; left = faster)"
set ylabel "mean |error| against the double-precision reference (log scale; lower = better)"
set label "ray-cast" at first 1.29472, first 2.47736e-08 left textcolor rgb "#008c00" front
set label "8x4" at first 2.22048, first 0.01434 left textcolor rgb "#1f64c8" front
set label "8x4" at first 1.67677, first 0.0259188 left textcolor rgb "#e07000" front
set label "16x8" at first 2.50059, first 0.00290768 left textcolor rgb "#1f64c8" front
set label "16x8" at first 1.57959, first 0.00880779 left textcolor rgb "#e07000" front
set label "32x16" at first 2.86766, first 0.000494019 left textcolor rgb "#1f64c8" front
set label "32x16" at first 1.73266, first 0.00273936 left textcolor rgb "#e07000" front
set label "64x32" at first 3.81256, first 0.000123424 left textcolor rgb "#1f64c8" front
set label "64x32" at first 1.82528, first 0.000756316 left textcolor rgb "#e07000" front
set label "128x64" at first 6.55347, first 3.07974e-05 left textcolor rgb "#1f64c8" front
set label "128x64" at first 4.99382, first 0.000193421 left textcolor rgb "#e07000" front
set label "eq.12 (Fig.10)" at first 2.49337, first 2.86596e-08 left textcolor rgb "#9646be" front
set label "eq.15 blinn" at first 2.78425, first 0.0128993 left textcolor rgb "#9646be" front
set label "eq.16 phong" at first 2.1517, first 0.02492 left textcolor rgb "#9646be" front
set label "specialized (9 figs)" at first 1.70819, first 1.02333e-08 left textcolor rgb "#00939a" front
set label "general (9 figs)" at first 4.49611, first 2.05808e-08 left textcolor rgb "#00939a" front
set label "CPU double (9 figs)" at first 13.5513, first 2.51189e-09 left textcolor rgb "#d21e1e" front
$group0 << EOD
1.78644 2.47736e-08
EOD
$group1 << EOD
2.09064 0.01434
2.35437 0.00290768
2.69997 0.000494019
3.58962 0.000123424
6.17025 3.07974e-05
EOD
$group2 << EOD
1.57872 0.0259188
1.48722 0.00880779
1.63134 0.00273936
2.28311 0.000756316
4.70181 0.000193421
EOD
$group3 << EOD
2.34757 2.86596e-08
2.62144 0.0128993
2.5758 0.0123908
EOD
$group4 << EOD
2.36915 2.05808e-08
4.2332 2.05808e-08
EOD
$group5 << EOD
12.7589 2.51189e-09
EOD
plot $group0 using 1:2 with points pt 7 ps 1.6 lc rgb "#008c00" title "exact ray-cast spheres (the renderer)", \
     $group1 using 1:2 with linespoints lw 1.5 pt 5 ps 1.6 lc rgb "#1f64c8" title "UV-sphere mesh, shaded per pixel (slices x stacks)", \
     $group2 using 1:2 with linespoints lw 1.5 pt 9 ps 1.6 lc rgb "#e07000" title "UV-sphere mesh, shaded per vertex (Gouraud)", \
     $group3 using 1:2 with points pt 13 ps 1.6 lc rgb "#9646be" title "the paper's metals: eq. 12, 15, 16 (error against eq. 12)", \
     $group4 using 1:2 with points pt 11 ps 1.6 lc rgb "#00939a" title "specialized against general programs (the paper's figures)", \
     $group5 using 1:2 with points pt 7 ps 1.6 lc rgb "#d21e1e" title "double-precision CPU reference (error 0 by definition)"
