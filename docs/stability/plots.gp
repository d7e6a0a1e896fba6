# gnuplot plots.gp (in docs/stability): the energy factor per step of an undamped spring against omega dt.
set terminal svg size 800,500 font 'sans,12'
set output 'springs.svg'
set logscale y
set yrange [0.08:100]
set xrange [0:3]
set xlabel 'omega dt'
set ylabel 'energy factor per step'
set key top left
set grid
plot 'springs.dat' using 1:2 with lines lc 1 title 'seed (theory)', 'springs-measured.dat' using 1:2 with points pt 7 lc 1 notitle, 'springs.dat' using 1:3 with lines lc 2 title 'explicit Euler (theory)', 'springs-measured.dat' using 1:3 with points pt 7 lc 2 notitle, 'springs.dat' using 1:4 with lines lc 3 title 'symplectic Euler (theory)', 'springs-measured.dat' using 1:4 with points pt 7 lc 3 notitle, 'springs.dat' using 1:5 with lines lc 4 title 'velocity Verlet (theory)', 'springs-measured.dat' using 1:5 with points pt 7 lc 4 notitle, 'springs.dat' using 1:6 with lines lc 5 title 'RK4 (theory)', 'springs-measured.dat' using 1:6 with points pt 7 lc 5 notitle, 'springs.dat' using 1:7 with lines lc 6 title 'symplectic4 (theory)', 'springs-measured.dat' using 1:7 with points pt 7 lc 6 notitle, 'springs.dat' using 1:8 with lines lc 7 title 'implicit Euler (theory)', 'springs-measured.dat' using 1:8 with points pt 7 lc 7 notitle, 'springs-measured.dat' using 1:9 with points pt 4 lc rgb 'black' title 'Chipmunk2D (measured)', 'springs-measured.dat' using 1:10 with points pt 6 lc rgb 'gray40' title 'Box2D 2.4 (measured)'
