set terminal svg size 760,500 dynamic font 'sans,11'
set logscale xy
set grid
set key outside right top
set format y '%.0e'
set format x '%g'
set output 'work-oscillator.svg'
set title "oscillator: error against CPU time (median; bars: range)"
set xlabel 'CPU time of the run (ms)'
set ylabel "phase-space error / amplitude"
plot 'oscillator-0.dat' using 3:2:4:5 with xerrorlines lt 1 title 'seed', 'oscillator-1.dat' using 3:2:4:5 with xerrorlines lt 2 title 'explicit Euler', 'oscillator-2.dat' using 3:2:4:5 with xerrorlines lt 3 title 'symplectic Euler', 'oscillator-3.dat' using 3:2:4:5 with xerrorlines lt 4 title 'velocity Verlet', 'oscillator-4.dat' using 3:2:4:5 with xerrorlines lt 5 title 'RK4', 'oscillator-5.dat' using 3:2:4:5 with xerrorlines lt 6 title 'symplectic4', 'oscillator-6.dat' using 3:2:4:5 with xerrorlines lt 7 title 'implicit Euler'
set output 'evaluations-oscillator.svg'
set title "oscillator: error against force evaluations"
set xlabel 'force evaluations (passes over the force creators)'
plot 'oscillator-0.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 1 title 'seed', 'oscillator-1.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 2 title 'explicit Euler', 'oscillator-2.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 3 title 'symplectic Euler', 'oscillator-3.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 4 title 'velocity Verlet', 'oscillator-4.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 5 title 'RK4', 'oscillator-5.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 6 title 'symplectic4', 'oscillator-6.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 7 title 'implicit Euler'
set output 'order-oscillator.svg'
set title "oscillator: error against h (filled: fit window)"
set xlabel 'step h (s)'
plot 'oscillator-0.dat' using 1:2 with linespoints lt 1 pt 6 title 'seed (slope 1.01)', 'oscillator-0.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 1 pt 7 notitle, 'oscillator-1.dat' using 1:2 with linespoints lt 2 pt 6 title 'explicit Euler (slope 1.01)', 'oscillator-1.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 2 pt 7 notitle, 'oscillator-2.dat' using 1:2 with linespoints lt 3 pt 6 title 'symplectic Euler (slope 1.02)', 'oscillator-2.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 3 pt 7 notitle, 'oscillator-3.dat' using 1:2 with linespoints lt 4 pt 6 title 'velocity Verlet (slope 2.00)', 'oscillator-3.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 4 pt 7 notitle, 'oscillator-4.dat' using 1:2 with linespoints lt 5 pt 6 title 'RK4 (slope 4.00)', 'oscillator-4.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 5 pt 7 notitle, 'oscillator-5.dat' using 1:2 with linespoints lt 6 pt 6 title 'symplectic4 (slope 4.00)', 'oscillator-5.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 6 pt 7 notitle, 'oscillator-6.dat' using 1:2 with linespoints lt 7 pt 6 title 'implicit Euler (slope 0.98)', 'oscillator-6.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 7 pt 7 notitle
set output 'work-kepler.svg'
set title "kepler: error against CPU time (median; bars: range)"
set xlabel 'CPU time of the run (ms)'
set ylabel "phase-space error of the relative motion"
plot 'kepler-0.dat' using 3:2:4:5 with xerrorlines lt 1 title 'seed', 'kepler-1.dat' using 3:2:4:5 with xerrorlines lt 2 title 'explicit Euler', 'kepler-2.dat' using 3:2:4:5 with xerrorlines lt 3 title 'symplectic Euler', 'kepler-3.dat' using 3:2:4:5 with xerrorlines lt 4 title 'velocity Verlet', 'kepler-4.dat' using 3:2:4:5 with xerrorlines lt 5 title 'RK4', 'kepler-5.dat' using 3:2:4:5 with xerrorlines lt 6 title 'symplectic4', 'kepler-6.dat' using 3:2:4:5 with xerrorlines lt 7 title 'implicit Euler'
set output 'evaluations-kepler.svg'
set title "kepler: error against force evaluations"
set xlabel 'force evaluations (passes over the force creators)'
plot 'kepler-0.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 1 title 'seed', 'kepler-1.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 2 title 'explicit Euler', 'kepler-2.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 3 title 'symplectic Euler', 'kepler-3.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 4 title 'velocity Verlet', 'kepler-4.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 5 title 'RK4', 'kepler-5.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 6 title 'symplectic4', 'kepler-6.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 7 title 'implicit Euler'
set output 'order-kepler.svg'
set title "kepler: error against h (filled: fit window)"
set xlabel 'step h (s)'
plot 'kepler-0.dat' using 1:2 with linespoints lt 1 pt 6 title 'seed (no window)', 'kepler-0.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 1 pt 7 notitle, 'kepler-1.dat' using 1:2 with linespoints lt 2 pt 6 title 'explicit Euler (no window)', 'kepler-1.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 2 pt 7 notitle, 'kepler-2.dat' using 1:2 with linespoints lt 3 pt 6 title 'symplectic Euler (slope 0.79)', 'kepler-2.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 3 pt 7 notitle, 'kepler-3.dat' using 1:2 with linespoints lt 4 pt 6 title 'velocity Verlet (slope 2.00)', 'kepler-3.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 4 pt 7 notitle, 'kepler-4.dat' using 1:2 with linespoints lt 5 pt 6 title 'RK4 (slope 4.16)', 'kepler-4.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 5 pt 7 notitle, 'kepler-5.dat' using 1:2 with linespoints lt 6 pt 6 title 'symplectic4 (slope 4.00)', 'kepler-5.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 6 pt 7 notitle, 'kepler-6.dat' using 1:2 with linespoints lt 7 pt 6 title 'implicit Euler (slope 0.79)', 'kepler-6.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 7 pt 7 notitle
set output 'work-kepler09.svg'
set title "kepler09: error against CPU time (median; bars: range)"
set xlabel 'CPU time of the run (ms)'
set ylabel "phase-space error of the relative motion"
plot 'kepler09-0.dat' using 3:2:4:5 with xerrorlines lt 1 title 'seed', 'kepler09-1.dat' using 3:2:4:5 with xerrorlines lt 2 title 'explicit Euler', 'kepler09-2.dat' using 3:2:4:5 with xerrorlines lt 3 title 'symplectic Euler', 'kepler09-3.dat' using 3:2:4:5 with xerrorlines lt 4 title 'velocity Verlet', 'kepler09-4.dat' using 3:2:4:5 with xerrorlines lt 5 title 'RK4', 'kepler09-5.dat' using 3:2:4:5 with xerrorlines lt 6 title 'symplectic4', 'kepler09-6.dat' using 3:2:4:5 with xerrorlines lt 7 title 'implicit Euler'
set output 'evaluations-kepler09.svg'
set title "kepler09: error against force evaluations"
set xlabel 'force evaluations (passes over the force creators)'
plot 'kepler09-0.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 1 title 'seed', 'kepler09-1.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 2 title 'explicit Euler', 'kepler09-2.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 3 title 'symplectic Euler', 'kepler09-3.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 4 title 'velocity Verlet', 'kepler09-4.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 5 title 'RK4', 'kepler09-5.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 6 title 'symplectic4', 'kepler09-6.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 7 title 'implicit Euler'
set output 'order-kepler09.svg'
set title "kepler09: error against h (filled: fit window)"
set xlabel 'step h (s)'
plot 'kepler09-0.dat' using 1:2 with linespoints lt 1 pt 6 title 'seed (no window)', 'kepler09-0.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 1 pt 7 notitle, 'kepler09-1.dat' using 1:2 with linespoints lt 2 pt 6 title 'explicit Euler (no window)', 'kepler09-1.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 2 pt 7 notitle, 'kepler09-2.dat' using 1:2 with linespoints lt 3 pt 6 title 'symplectic Euler (no window)', 'kepler09-2.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 3 pt 7 notitle, 'kepler09-3.dat' using 1:2 with linespoints lt 4 pt 6 title 'velocity Verlet (no window)', 'kepler09-3.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 4 pt 7 notitle, 'kepler09-4.dat' using 1:2 with linespoints lt 5 pt 6 title 'RK4 (slope 4.54)', 'kepler09-4.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 5 pt 7 notitle, 'kepler09-5.dat' using 1:2 with linespoints lt 6 pt 6 title 'symplectic4 (slope 3.99)', 'kepler09-5.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 6 pt 7 notitle, 'kepler09-6.dat' using 1:2 with linespoints lt 7 pt 6 title 'implicit Euler (no window)', 'kepler09-6.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 7 pt 7 notitle
set output 'work-orbit.svg'
set title "orbit: error against CPU time (median; bars: range)"
set xlabel 'CPU time of the run (ms)'
set ylabel "phase-space error of the relative motion"
plot 'orbit-0.dat' using 3:2:4:5 with xerrorlines lt 1 title 'seed', 'orbit-1.dat' using 3:2:4:5 with xerrorlines lt 2 title 'explicit Euler', 'orbit-2.dat' using 3:2:4:5 with xerrorlines lt 3 title 'symplectic Euler', 'orbit-3.dat' using 3:2:4:5 with xerrorlines lt 4 title 'velocity Verlet', 'orbit-4.dat' using 3:2:4:5 with xerrorlines lt 5 title 'RK4', 'orbit-5.dat' using 3:2:4:5 with xerrorlines lt 6 title 'symplectic4', 'orbit-6.dat' using 3:2:4:5 with xerrorlines lt 7 title 'implicit Euler'
set output 'evaluations-orbit.svg'
set title "orbit: error against force evaluations"
set xlabel 'force evaluations (passes over the force creators)'
plot 'orbit-0.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 1 title 'seed', 'orbit-1.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 2 title 'explicit Euler', 'orbit-2.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 3 title 'symplectic Euler', 'orbit-3.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 4 title 'velocity Verlet', 'orbit-4.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 5 title 'RK4', 'orbit-5.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 6 title 'symplectic4', 'orbit-6.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 7 title 'implicit Euler'
set output 'order-orbit.svg'
set title "orbit: error against h (filled: fit window)"
set xlabel 'step h (s)'
plot 'orbit-0.dat' using 1:2 with linespoints lt 1 pt 6 title 'seed (no window)', 'orbit-0.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 1 pt 7 notitle, 'orbit-1.dat' using 1:2 with linespoints lt 2 pt 6 title 'explicit Euler (no window)', 'orbit-1.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 2 pt 7 notitle, 'orbit-2.dat' using 1:2 with linespoints lt 3 pt 6 title 'symplectic Euler (slope 0.95)', 'orbit-2.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 3 pt 7 notitle, 'orbit-3.dat' using 1:2 with linespoints lt 4 pt 6 title 'velocity Verlet (slope 2.00)', 'orbit-3.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 4 pt 7 notitle, 'orbit-4.dat' using 1:2 with linespoints lt 5 pt 6 title 'RK4 (slope 4.21)', 'orbit-4.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 5 pt 7 notitle, 'orbit-5.dat' using 1:2 with linespoints lt 6 pt 6 title 'symplectic4 (slope 4.02)', 'orbit-5.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 6 pt 7 notitle, 'orbit-6.dat' using 1:2 with linespoints lt 7 pt 6 title 'implicit Euler (slope 0.95)', 'orbit-6.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 7 pt 7 notitle
set output 'work-drag.svg'
set title "drag: error against CPU time (median; bars: range)"
set xlabel 'CPU time of the run (ms)'
set ylabel "position error / distance flown"
plot 'drag-0.dat' using 3:2:4:5 with xerrorlines lt 1 title 'seed', 'drag-1.dat' using 3:2:4:5 with xerrorlines lt 2 title 'explicit Euler', 'drag-2.dat' using 3:2:4:5 with xerrorlines lt 3 title 'symplectic Euler', 'drag-3.dat' using 3:2:4:5 with xerrorlines lt 4 title 'velocity Verlet', 'drag-4.dat' using 3:2:4:5 with xerrorlines lt 5 title 'RK4', 'drag-5.dat' using 3:2:4:5 with xerrorlines lt 6 title 'symplectic4', 'drag-6.dat' using 3:2:4:5 with xerrorlines lt 7 title 'implicit Euler'
set output 'evaluations-drag.svg'
set title "drag: error against force evaluations"
set xlabel 'force evaluations (passes over the force creators)'
plot 'drag-0.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 1 title 'seed', 'drag-1.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 2 title 'explicit Euler', 'drag-2.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 3 title 'symplectic Euler', 'drag-3.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 4 title 'velocity Verlet', 'drag-4.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 5 title 'RK4', 'drag-5.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 6 title 'symplectic4', 'drag-6.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 7 title 'implicit Euler'
set output 'order-drag.svg'
set title "drag: error against h (filled: fit window)"
set xlabel 'step h (s)'
plot 'drag-0.dat' using 1:2 with linespoints lt 1 pt 6 title 'seed (slope 1.00)', 'drag-0.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 1 pt 7 notitle, 'drag-1.dat' using 1:2 with linespoints lt 2 pt 6 title 'explicit Euler (slope 1.00)', 'drag-1.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 2 pt 7 notitle, 'drag-2.dat' using 1:2 with linespoints lt 3 pt 6 title 'symplectic Euler (slope 1.00)', 'drag-2.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 3 pt 7 notitle, 'drag-3.dat' using 1:2 with linespoints lt 4 pt 6 title 'velocity Verlet (slope 2.01)', 'drag-3.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 4 pt 7 notitle, 'drag-4.dat' using 1:2 with linespoints lt 5 pt 6 title 'RK4 (slope 4.05)', 'drag-4.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 5 pt 7 notitle, 'drag-5.dat' using 1:2 with linespoints lt 6 pt 6 title 'symplectic4 (slope 1.99)', 'drag-5.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 6 pt 7 notitle, 'drag-6.dat' using 1:2 with linespoints lt 7 pt 6 title 'implicit Euler (slope 1.00)', 'drag-6.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 7 pt 7 notitle
set output 'work-bounce.svg'
set title "bounce: error against CPU time (median; bars: range)"
set xlabel 'CPU time of the run (ms)'
set ylabel "largest relative apex error (5 apexes)"
plot 'bounce-0.dat' using 3:2:4:5 with xerrorlines lt 1 title 'seed', 'bounce-1.dat' using 3:2:4:5 with xerrorlines lt 2 title 'explicit Euler', 'bounce-2.dat' using 3:2:4:5 with xerrorlines lt 3 title 'symplectic Euler', 'bounce-3.dat' using 3:2:4:5 with xerrorlines lt 4 title 'velocity Verlet', 'bounce-4.dat' using 3:2:4:5 with xerrorlines lt 5 title 'RK4', 'bounce-5.dat' using 3:2:4:5 with xerrorlines lt 6 title 'symplectic4', 'bounce-6.dat' using 3:2:4:5 with xerrorlines lt 7 title 'implicit Euler'
set title "bounce: error against force evaluations"
set xlabel 'force evaluations (passes over the force creators)'
set output 'order-bounce.svg'
set title "bounce: error against h (filled: fit window)"
set xlabel 'step h (s)'
plot 'bounce-0.dat' using 1:2 with linespoints lt 1 pt 6 title 'seed (no window)', 'bounce-0.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 1 pt 7 notitle, 'bounce-1.dat' using 1:2 with linespoints lt 2 pt 6 title 'explicit Euler (slope 1.00)', 'bounce-1.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 2 pt 7 notitle, 'bounce-2.dat' using 1:2 with linespoints lt 3 pt 6 title 'symplectic Euler (slope 1.00)', 'bounce-2.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 3 pt 7 notitle, 'bounce-3.dat' using 1:2 with linespoints lt 4 pt 6 title 'velocity Verlet (no window)', 'bounce-3.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 4 pt 7 notitle, 'bounce-4.dat' using 1:2 with linespoints lt 5 pt 6 title 'RK4 (no window)', 'bounce-4.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 5 pt 7 notitle, 'bounce-5.dat' using 1:2 with linespoints lt 6 pt 6 title 'symplectic4 (no window)', 'bounce-5.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 6 pt 7 notitle, 'bounce-6.dat' using 1:2 with linespoints lt 7 pt 6 title 'implicit Euler (slope 1.00)', 'bounce-6.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 7 pt 7 notitle
set output 'growth-oscillator.svg'
set terminal svg size 1200,440 dynamic font 'sans,10'
set multiplot layout 1,2 title "oscillator: errors against time at 8 steps per period"
set xlabel 'periods'
set title "largest |E/E0 - 1| since the last point"
set ylabel ''
unset key
plot 'horizon-oscillator-0-0.dat' using 1:2 with lines lt 1 lw 1.5 title 'seed', 'horizon-oscillator-1-0.dat' using 1:2 with lines lt 2 lw 1.5 title 'explicit Euler', 'horizon-oscillator-2-0.dat' using 1:2 with lines lt 3 lw 1.5 title 'symplectic Euler', 'horizon-oscillator-3-0.dat' using 1:2 with lines lt 4 lw 1.5 title 'velocity Verlet', 'horizon-oscillator-4-0.dat' using 1:2 with lines lt 5 lw 1.5 title 'RK4', 'horizon-oscillator-5-0.dat' using 1:2 with lines lt 6 lw 1.5 title 'symplectic4', 'horizon-oscillator-6-0.dat' using 1:2 with lines lt 7 lw 1.5 title 'implicit Euler'
set title "phase (position) error / semi-major axis"
set ylabel ''
set key outside below horizontal maxrows 2
plot 'horizon-oscillator-0-0.dat' using 1:4 with lines lt 1 lw 1.5 title 'seed', 'horizon-oscillator-1-0.dat' using 1:4 with lines lt 2 lw 1.5 title 'explicit Euler', 'horizon-oscillator-2-0.dat' using 1:4 with lines lt 3 lw 1.5 title 'symplectic Euler', 'horizon-oscillator-3-0.dat' using 1:4 with lines lt 4 lw 1.5 title 'velocity Verlet', 'horizon-oscillator-4-0.dat' using 1:4 with lines lt 5 lw 1.5 title 'RK4', 'horizon-oscillator-5-0.dat' using 1:4 with lines lt 6 lw 1.5 title 'symplectic4', 'horizon-oscillator-6-0.dat' using 1:4 with lines lt 7 lw 1.5 title 'implicit Euler'
unset multiplot
set output 'precision-oscillator.svg'
set multiplot layout 1,3 title "oscillator: error at a horizon against the CPU time to reach it (one point per step size)"
set xlabel 'CPU ms (steps x median per step)'
unset key
set title '10 periods'
unset key
plot 'precision-oscillator-0-0.dat' using 2:1:3:4 with xerrorlines lt 1 title 'seed', 'precision-oscillator-0-1.dat' using 2:1:3:4 with xerrorlines lt 2 title 'explicit Euler', 'precision-oscillator-0-2.dat' using 2:1:3:4 with xerrorlines lt 3 title 'symplectic Euler', 'precision-oscillator-0-3.dat' using 2:1:3:4 with xerrorlines lt 4 title 'velocity Verlet', 'precision-oscillator-0-4.dat' using 2:1:3:4 with xerrorlines lt 5 title 'RK4', 'precision-oscillator-0-5.dat' using 2:1:3:4 with xerrorlines lt 6 title 'symplectic4', 'precision-oscillator-0-6.dat' using 2:1:3:4 with xerrorlines lt 7 title 'implicit Euler'
set title '1000 periods'
unset key
plot 'precision-oscillator-1-2.dat' using 2:1:3:4 with xerrorlines lt 3 title 'symplectic Euler', 'precision-oscillator-1-3.dat' using 2:1:3:4 with xerrorlines lt 4 title 'velocity Verlet', 'precision-oscillator-1-4.dat' using 2:1:3:4 with xerrorlines lt 5 title 'RK4', 'precision-oscillator-1-5.dat' using 2:1:3:4 with xerrorlines lt 6 title 'symplectic4', 'precision-oscillator-1-6.dat' using 2:1:3:4 with xerrorlines lt 7 title 'implicit Euler'
set title '100000 periods'
set key outside below horizontal maxrows 2
plot 'precision-oscillator-2-2.dat' using 2:1:3:4 with xerrorlines lt 3 title 'symplectic Euler', 'precision-oscillator-2-3.dat' using 2:1:3:4 with xerrorlines lt 4 title 'velocity Verlet', 'precision-oscillator-2-4.dat' using 2:1:3:4 with xerrorlines lt 5 title 'RK4', 'precision-oscillator-2-5.dat' using 2:1:3:4 with xerrorlines lt 6 title 'symplectic4', 'precision-oscillator-2-6.dat' using 2:1:3:4 with xerrorlines lt 7 title 'implicit Euler'
unset multiplot
set terminal svg size 760,500 dynamic font 'sans,11'
set key outside right top
set output 'growth-kepler.svg'
set terminal svg size 1200,440 dynamic font 'sans,10'
set multiplot layout 1,3 title "kepler: errors against time at 64 steps per period"
set xlabel 'periods'
set title "largest |E/E0 - 1| since the last point"
set ylabel ''
unset key
plot 'horizon-kepler-0-2.dat' using 1:2 with lines lt 1 lw 1.5 title 'seed', 'horizon-kepler-1-2.dat' using 1:2 with lines lt 2 lw 1.5 title 'explicit Euler', 'horizon-kepler-2-2.dat' using 1:2 with lines lt 3 lw 1.5 title 'symplectic Euler', 'horizon-kepler-3-2.dat' using 1:2 with lines lt 4 lw 1.5 title 'velocity Verlet', 'horizon-kepler-4-2.dat' using 1:2 with lines lt 5 lw 1.5 title 'RK4', 'horizon-kepler-5-2.dat' using 1:2 with lines lt 6 lw 1.5 title 'symplectic4', 'horizon-kepler-6-2.dat' using 1:2 with lines lt 7 lw 1.5 title 'implicit Euler'
set title "largest |L/L0 - 1| since the last point"
set ylabel ''
unset key
plot 'horizon-kepler-0-2.dat' using 1:3 with lines lt 1 lw 1.5 title 'seed', 'horizon-kepler-1-2.dat' using 1:3 with lines lt 2 lw 1.5 title 'explicit Euler', 'horizon-kepler-2-2.dat' using 1:3 with lines lt 3 lw 1.5 title 'symplectic Euler', 'horizon-kepler-3-2.dat' using 1:3 with lines lt 4 lw 1.5 title 'velocity Verlet', 'horizon-kepler-4-2.dat' using 1:3 with lines lt 5 lw 1.5 title 'RK4', 'horizon-kepler-5-2.dat' using 1:3 with lines lt 6 lw 1.5 title 'symplectic4', 'horizon-kepler-6-2.dat' using 1:3 with lines lt 7 lw 1.5 title 'implicit Euler'
set title "phase (position) error / semi-major axis"
set ylabel ''
set key outside below horizontal maxrows 2
plot 'horizon-kepler-0-2.dat' using 1:4 with lines lt 1 lw 1.5 title 'seed', 'horizon-kepler-1-2.dat' using 1:4 with lines lt 2 lw 1.5 title 'explicit Euler', 'horizon-kepler-2-2.dat' using 1:4 with lines lt 3 lw 1.5 title 'symplectic Euler', 'horizon-kepler-3-2.dat' using 1:4 with lines lt 4 lw 1.5 title 'velocity Verlet', 'horizon-kepler-4-2.dat' using 1:4 with lines lt 5 lw 1.5 title 'RK4', 'horizon-kepler-5-2.dat' using 1:4 with lines lt 6 lw 1.5 title 'symplectic4', 'horizon-kepler-6-2.dat' using 1:4 with lines lt 7 lw 1.5 title 'implicit Euler'
unset multiplot
set output 'precision-kepler.svg'
set multiplot layout 1,3 title "kepler: error at a horizon against the CPU time to reach it (one point per step size)"
set xlabel 'CPU ms (steps x median per step)'
unset key
set title '10 periods'
unset key
plot 'precision-kepler-0-0.dat' using 2:1:3:4 with xerrorlines lt 1 title 'seed', 'precision-kepler-0-1.dat' using 2:1:3:4 with xerrorlines lt 2 title 'explicit Euler', 'precision-kepler-0-2.dat' using 2:1:3:4 with xerrorlines lt 3 title 'symplectic Euler', 'precision-kepler-0-3.dat' using 2:1:3:4 with xerrorlines lt 4 title 'velocity Verlet', 'precision-kepler-0-4.dat' using 2:1:3:4 with xerrorlines lt 5 title 'RK4', 'precision-kepler-0-5.dat' using 2:1:3:4 with xerrorlines lt 6 title 'symplectic4', 'precision-kepler-0-6.dat' using 2:1:3:4 with xerrorlines lt 7 title 'implicit Euler'
set title '1000 periods'
unset key
plot 'precision-kepler-1-0.dat' using 2:1:3:4 with xerrorlines lt 1 title 'seed', 'precision-kepler-1-1.dat' using 2:1:3:4 with xerrorlines lt 2 title 'explicit Euler', 'precision-kepler-1-2.dat' using 2:1:3:4 with xerrorlines lt 3 title 'symplectic Euler', 'precision-kepler-1-3.dat' using 2:1:3:4 with xerrorlines lt 4 title 'velocity Verlet', 'precision-kepler-1-4.dat' using 2:1:3:4 with xerrorlines lt 5 title 'RK4', 'precision-kepler-1-5.dat' using 2:1:3:4 with xerrorlines lt 6 title 'symplectic4', 'precision-kepler-1-6.dat' using 2:1:3:4 with xerrorlines lt 7 title 'implicit Euler'
set title '100000 periods'
set key outside below horizontal maxrows 2
plot 'precision-kepler-2-0.dat' using 2:1:3:4 with xerrorlines lt 1 title 'seed', 'precision-kepler-2-1.dat' using 2:1:3:4 with xerrorlines lt 2 title 'explicit Euler', 'precision-kepler-2-2.dat' using 2:1:3:4 with xerrorlines lt 3 title 'symplectic Euler', 'precision-kepler-2-3.dat' using 2:1:3:4 with xerrorlines lt 4 title 'velocity Verlet', 'precision-kepler-2-4.dat' using 2:1:3:4 with xerrorlines lt 5 title 'RK4', 'precision-kepler-2-5.dat' using 2:1:3:4 with xerrorlines lt 6 title 'symplectic4', 'precision-kepler-2-6.dat' using 2:1:3:4 with xerrorlines lt 7 title 'implicit Euler'
unset multiplot
set terminal svg size 760,500 dynamic font 'sans,11'
set key outside right top
set output 'growth-kepler09.svg'
set terminal svg size 1200,440 dynamic font 'sans,10'
set multiplot layout 1,3 title "kepler09: errors against time at 64 steps per period"
set xlabel 'periods'
set title "largest |E/E0 - 1| since the last point"
set ylabel ''
unset key
plot 'horizon-kepler09-0-1.dat' using 1:2 with lines lt 1 lw 1.5 title 'seed', 'horizon-kepler09-1-1.dat' using 1:2 with lines lt 2 lw 1.5 title 'explicit Euler', 'horizon-kepler09-2-1.dat' using 1:2 with lines lt 3 lw 1.5 title 'symplectic Euler', 'horizon-kepler09-3-1.dat' using 1:2 with lines lt 4 lw 1.5 title 'velocity Verlet', 'horizon-kepler09-4-1.dat' using 1:2 with lines lt 5 lw 1.5 title 'RK4', 'horizon-kepler09-5-1.dat' using 1:2 with lines lt 6 lw 1.5 title 'symplectic4', 'horizon-kepler09-6-1.dat' using 1:2 with lines lt 7 lw 1.5 title 'implicit Euler'
set title "largest |L/L0 - 1| since the last point"
set ylabel ''
unset key
plot 'horizon-kepler09-0-1.dat' using 1:3 with lines lt 1 lw 1.5 title 'seed', 'horizon-kepler09-1-1.dat' using 1:3 with lines lt 2 lw 1.5 title 'explicit Euler', 'horizon-kepler09-2-1.dat' using 1:3 with lines lt 3 lw 1.5 title 'symplectic Euler', 'horizon-kepler09-3-1.dat' using 1:3 with lines lt 4 lw 1.5 title 'velocity Verlet', 'horizon-kepler09-4-1.dat' using 1:3 with lines lt 5 lw 1.5 title 'RK4', 'horizon-kepler09-5-1.dat' using 1:3 with lines lt 6 lw 1.5 title 'symplectic4', 'horizon-kepler09-6-1.dat' using 1:3 with lines lt 7 lw 1.5 title 'implicit Euler'
set title "phase (position) error / semi-major axis"
set ylabel ''
set key outside below horizontal maxrows 2
plot 'horizon-kepler09-0-1.dat' using 1:4 with lines lt 1 lw 1.5 title 'seed', 'horizon-kepler09-1-1.dat' using 1:4 with lines lt 2 lw 1.5 title 'explicit Euler', 'horizon-kepler09-2-1.dat' using 1:4 with lines lt 3 lw 1.5 title 'symplectic Euler', 'horizon-kepler09-3-1.dat' using 1:4 with lines lt 4 lw 1.5 title 'velocity Verlet', 'horizon-kepler09-4-1.dat' using 1:4 with lines lt 5 lw 1.5 title 'RK4', 'horizon-kepler09-5-1.dat' using 1:4 with lines lt 6 lw 1.5 title 'symplectic4', 'horizon-kepler09-6-1.dat' using 1:4 with lines lt 7 lw 1.5 title 'implicit Euler'
unset multiplot
set output 'precision-kepler09.svg'
set multiplot layout 1,3 title "kepler09: error at a horizon against the CPU time to reach it (one point per step size)"
set xlabel 'CPU ms (steps x median per step)'
unset key
set title '10 periods'
unset key
plot 'precision-kepler09-0-0.dat' using 2:1:3:4 with xerrorlines lt 1 title 'seed', 'precision-kepler09-0-1.dat' using 2:1:3:4 with xerrorlines lt 2 title 'explicit Euler', 'precision-kepler09-0-2.dat' using 2:1:3:4 with xerrorlines lt 3 title 'symplectic Euler', 'precision-kepler09-0-3.dat' using 2:1:3:4 with xerrorlines lt 4 title 'velocity Verlet', 'precision-kepler09-0-4.dat' using 2:1:3:4 with xerrorlines lt 5 title 'RK4', 'precision-kepler09-0-5.dat' using 2:1:3:4 with xerrorlines lt 6 title 'symplectic4', 'precision-kepler09-0-6.dat' using 2:1:3:4 with xerrorlines lt 7 title 'implicit Euler'
set title '1000 periods'
unset key
plot 'precision-kepler09-1-0.dat' using 2:1:3:4 with xerrorlines lt 1 title 'seed', 'precision-kepler09-1-1.dat' using 2:1:3:4 with xerrorlines lt 2 title 'explicit Euler', 'precision-kepler09-1-2.dat' using 2:1:3:4 with xerrorlines lt 3 title 'symplectic Euler', 'precision-kepler09-1-3.dat' using 2:1:3:4 with xerrorlines lt 4 title 'velocity Verlet', 'precision-kepler09-1-4.dat' using 2:1:3:4 with xerrorlines lt 5 title 'RK4', 'precision-kepler09-1-5.dat' using 2:1:3:4 with xerrorlines lt 6 title 'symplectic4', 'precision-kepler09-1-6.dat' using 2:1:3:4 with xerrorlines lt 7 title 'implicit Euler'
set title '100000 periods'
set key outside below horizontal maxrows 2
plot 'precision-kepler09-2-0.dat' using 2:1:3:4 with xerrorlines lt 1 title 'seed', 'precision-kepler09-2-1.dat' using 2:1:3:4 with xerrorlines lt 2 title 'explicit Euler', 'precision-kepler09-2-2.dat' using 2:1:3:4 with xerrorlines lt 3 title 'symplectic Euler', 'precision-kepler09-2-3.dat' using 2:1:3:4 with xerrorlines lt 4 title 'velocity Verlet', 'precision-kepler09-2-4.dat' using 2:1:3:4 with xerrorlines lt 5 title 'RK4', 'precision-kepler09-2-5.dat' using 2:1:3:4 with xerrorlines lt 6 title 'symplectic4', 'precision-kepler09-2-6.dat' using 2:1:3:4 with xerrorlines lt 7 title 'implicit Euler'
unset multiplot
set terminal svg size 760,500 dynamic font 'sans,11'
set key outside right top
set terminal svg size 1520,720 dynamic font 'sans,10'
unset logscale
set format x '%g'
set format y '%g'
set size ratio -1
set contour base
set cntrparam levels discrete 1
unset surface
set view map
set table 'region-0.contour'
splot 'region-0.grid' using 1:2:3 with lines
unset table
set table 'region-1.contour'
splot 'region-1.grid' using 1:2:3 with lines
unset table
set table 'region-2.contour'
splot 'region-2.grid' using 1:2:3 with lines
unset table
set table 'region-3.contour'
splot 'region-3.grid' using 1:2:3 with lines
unset table
set table 'region-4.contour'
splot 'region-4.grid' using 1:2:3 with lines
unset table
set table 'region-5.contour'
splot 'region-5.grid' using 1:2:3 with lines
unset table
set table 'region-6.contour'
splot 'region-6.grid' using 1:2:3 with lines
unset table
set output 'regions.svg'
set multiplot layout 2,4 title "Spectral radius 1 (closed form, line); the engine's limits (dots: damped springs; square: drag alone)"
set xrange [-5:0.5]
set yrange [-4:4]
unset key
set xlabel 'Re h lambda'
set ylabel 'Im h lambda'
set title 'seed'
plot 'region-0.contour' with lines lt 1 lw 1.5, 'region-0-measured.dat' with points pt 7 lc rgb 'black', 'region-0-measured.dat' using 1:(-$2) with points pt 7 lc rgb 'black', 'region-0-drag.dat' with points pt 5 ps 1.2 lc rgb 'red', 0 with lines lc rgb 'grey'
set title 'explicit Euler'
plot 'region-1.contour' with lines lt 1 lw 1.5, 'region-1-measured.dat' with points pt 7 lc rgb 'black', 'region-1-measured.dat' using 1:(-$2) with points pt 7 lc rgb 'black', 'region-1-drag.dat' with points pt 5 ps 1.2 lc rgb 'red', 0 with lines lc rgb 'grey'
set title 'symplectic Euler'
plot 'region-2.contour' with lines lt 1 lw 1.5, 'region-2-measured.dat' with points pt 7 lc rgb 'black', 'region-2-measured.dat' using 1:(-$2) with points pt 7 lc rgb 'black', 'region-2-drag.dat' with points pt 5 ps 1.2 lc rgb 'red', 0 with lines lc rgb 'grey'
set title 'velocity Verlet'
plot 'region-3.contour' with lines lt 1 lw 1.5, 'region-3-measured.dat' with points pt 7 lc rgb 'black', 'region-3-measured.dat' using 1:(-$2) with points pt 7 lc rgb 'black', 'region-3-drag.dat' with points pt 5 ps 1.2 lc rgb 'red', 0 with lines lc rgb 'grey'
set title 'RK4'
plot 'region-4.contour' with lines lt 1 lw 1.5, 'region-4-measured.dat' with points pt 7 lc rgb 'black', 'region-4-measured.dat' using 1:(-$2) with points pt 7 lc rgb 'black', 'region-4-drag.dat' with points pt 5 ps 1.2 lc rgb 'red', 0 with lines lc rgb 'grey'
set title 'symplectic4'
plot 'region-5.contour' with lines lt 1 lw 1.5, 'region-5-measured.dat' with points pt 7 lc rgb 'black', 'region-5-measured.dat' using 1:(-$2) with points pt 7 lc rgb 'black', 'region-5-drag.dat' with points pt 5 ps 1.2 lc rgb 'red', 0 with lines lc rgb 'grey'
set title 'implicit Euler'
plot 'region-6.contour' with lines lt 1 lw 1.5, 0 with lines lc rgb 'grey'
unset multiplot
unset contour
set surface
unset view
set size noratio
unset xrange
unset yrange
set autoscale
set logscale xy
set format y '%.0e'
set terminal svg size 760,500 dynamic font 'sans,11'
set key outside right top
set output 'work-friction_spring.svg'
set title "friction_spring: error against CPU time (median; bars: range)"
set xlabel 'CPU time of the run (ms)'
set ylabel "position error / initial stretch"
plot 'friction_spring-0.dat' using 3:2:4:5 with xerrorlines lt 1 title 'seed', 'friction_spring-1.dat' using 3:2:4:5 with xerrorlines lt 2 title 'explicit Euler', 'friction_spring-2.dat' using 3:2:4:5 with xerrorlines lt 3 title 'symplectic Euler', 'friction_spring-3.dat' using 3:2:4:5 with xerrorlines lt 4 title 'velocity Verlet', 'friction_spring-4.dat' using 3:2:4:5 with xerrorlines lt 5 title 'RK4', 'friction_spring-5.dat' using 3:2:4:5 with xerrorlines lt 6 title 'symplectic4', 'friction_spring-6.dat' using 3:2:4:5 with xerrorlines lt 7 title 'implicit Euler'
set output 'evaluations-friction_spring.svg'
set title "friction_spring: error against force evaluations"
set xlabel 'force evaluations (passes over the force creators)'
plot 'friction_spring-0.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 1 title 'seed', 'friction_spring-1.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 2 title 'explicit Euler', 'friction_spring-2.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 3 title 'symplectic Euler', 'friction_spring-3.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 4 title 'velocity Verlet', 'friction_spring-4.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 5 title 'RK4', 'friction_spring-5.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 6 title 'symplectic4', 'friction_spring-6.dat' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt 7 title 'implicit Euler'
set output 'order-friction_spring.svg'
set title "friction_spring: error against h (filled: fit window)"
set xlabel 'step h (s)'
plot 'friction_spring-0.dat' using 1:2 with linespoints lt 1 pt 6 title 'seed (slope 0.97)', 'friction_spring-0.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 1 pt 7 notitle, 'friction_spring-1.dat' using 1:2 with linespoints lt 2 pt 6 title 'explicit Euler (slope 2.06)', 'friction_spring-1.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 2 pt 7 notitle, 'friction_spring-2.dat' using 1:2 with linespoints lt 3 pt 6 title 'symplectic Euler (slope 1.01)', 'friction_spring-2.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 3 pt 7 notitle, 'friction_spring-3.dat' using 1:2 with linespoints lt 4 pt 6 title 'velocity Verlet (slope 2.01)', 'friction_spring-3.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 4 pt 7 notitle, 'friction_spring-4.dat' using 1:2 with linespoints lt 5 pt 6 title 'RK4 (slope 2.85)', 'friction_spring-4.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 5 pt 7 notitle, 'friction_spring-5.dat' using 1:2 with linespoints lt 6 pt 6 title 'symplectic4 (slope 4.43)', 'friction_spring-5.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 6 pt 7 notitle, 'friction_spring-6.dat' using 1:2 with linespoints lt 7 pt 6 title 'implicit Euler (slope 1.94)', 'friction_spring-6.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 7 pt 7 notitle
set output 'work-incline_below.svg'
set title "incline_below: error against CPU time (median; bars: range)"
set xlabel 'CPU time of the run (ms)'
set ylabel "distance slid (m)"
plot 'incline_below-0.dat' using 3:2:4:5 with xerrorlines lt 1 title 'seed', 'incline_below-1.dat' using 3:2:4:5 with xerrorlines lt 2 title 'explicit Euler', 'incline_below-2.dat' using 3:2:4:5 with xerrorlines lt 3 title 'symplectic Euler', 'incline_below-3.dat' using 3:2:4:5 with xerrorlines lt 4 title 'velocity Verlet', 'incline_below-4.dat' using 3:2:4:5 with xerrorlines lt 5 title 'RK4', 'incline_below-5.dat' using 3:2:4:5 with xerrorlines lt 6 title 'symplectic4', 'incline_below-6.dat' using 3:2:4:5 with xerrorlines lt 7 title 'implicit Euler'
set title "incline_below: error against force evaluations"
set xlabel 'force evaluations (passes over the force creators)'
set output 'order-incline_below.svg'
set title "incline_below: error against h (filled: fit window)"
set xlabel 'step h (s)'
plot 'incline_below-0.dat' using 1:2 with linespoints lt 1 pt 6 title 'seed (slope 2.00)', 'incline_below-0.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 1 pt 7 notitle, 'incline_below-1.dat' using 1:2 with linespoints lt 2 pt 6 title 'explicit Euler (slope 2.00)', 'incline_below-1.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 2 pt 7 notitle, 'incline_below-2.dat' using 1:2 with linespoints lt 3 pt 6 title 'symplectic Euler (slope 2.00)', 'incline_below-2.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 3 pt 7 notitle, 'incline_below-3.dat' using 1:2 with linespoints lt 4 pt 6 title 'velocity Verlet (slope 2.00)', 'incline_below-3.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 4 pt 7 notitle, 'incline_below-4.dat' using 1:2 with linespoints lt 5 pt 6 title 'RK4 (slope 2.00)', 'incline_below-4.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 5 pt 7 notitle, 'incline_below-5.dat' using 1:2 with linespoints lt 6 pt 6 title 'symplectic4 (slope 2.00)', 'incline_below-5.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 6 pt 7 notitle, 'incline_below-6.dat' using 1:2 with linespoints lt 7 pt 6 title 'implicit Euler (slope 2.00)', 'incline_below-6.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 7 pt 7 notitle
set output 'work-incline_above.svg'
set title "incline_above: error against CPU time (median; bars: range)"
set xlabel 'CPU time of the run (ms)'
set ylabel "relative error of the distance slid"
plot 'incline_above-0.dat' using 3:2:4:5 with xerrorlines lt 1 title 'seed', 'incline_above-1.dat' using 3:2:4:5 with xerrorlines lt 2 title 'explicit Euler', 'incline_above-2.dat' using 3:2:4:5 with xerrorlines lt 3 title 'symplectic Euler', 'incline_above-3.dat' using 3:2:4:5 with xerrorlines lt 4 title 'velocity Verlet', 'incline_above-4.dat' using 3:2:4:5 with xerrorlines lt 5 title 'RK4', 'incline_above-5.dat' using 3:2:4:5 with xerrorlines lt 6 title 'symplectic4', 'incline_above-6.dat' using 3:2:4:5 with xerrorlines lt 7 title 'implicit Euler'
set title "incline_above: error against force evaluations"
set xlabel 'force evaluations (passes over the force creators)'
set output 'order-incline_above.svg'
set title "incline_above: error against h (filled: fit window)"
set xlabel 'step h (s)'
plot 'incline_above-0.dat' using 1:2 with linespoints lt 1 pt 6 title 'seed (no window)', 'incline_above-0.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 1 pt 7 notitle, 'incline_above-1.dat' using 1:2 with linespoints lt 2 pt 6 title 'explicit Euler (slope 1.00)', 'incline_above-1.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 2 pt 7 notitle, 'incline_above-2.dat' using 1:2 with linespoints lt 3 pt 6 title 'symplectic Euler (slope 1.00)', 'incline_above-2.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 3 pt 7 notitle, 'incline_above-3.dat' using 1:2 with linespoints lt 4 pt 6 title 'velocity Verlet (no window)', 'incline_above-3.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 4 pt 7 notitle, 'incline_above-4.dat' using 1:2 with linespoints lt 5 pt 6 title 'RK4 (no window)', 'incline_above-4.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 5 pt 7 notitle, 'incline_above-5.dat' using 1:2 with linespoints lt 6 pt 6 title 'symplectic4 (no window)', 'incline_above-5.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 6 pt 7 notitle, 'incline_above-6.dat' using 1:2 with linespoints lt 7 pt 6 title 'implicit Euler (slope 1.00)', 'incline_above-6.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 7 pt 7 notitle
set output 'work-rocking.svg'
set title "rocking: error against CPU time (median; bars: range)"
set xlabel 'CPU time of the run (ms)'
set ylabel "tilt error / initial tilt"
plot 'rocking-0.dat' using 3:2:4:5 with xerrorlines lt 1 title 'seed', 'rocking-1.dat' using 3:2:4:5 with xerrorlines lt 2 title 'explicit Euler', 'rocking-2.dat' using 3:2:4:5 with xerrorlines lt 3 title 'symplectic Euler', 'rocking-3.dat' using 3:2:4:5 with xerrorlines lt 4 title 'velocity Verlet', 'rocking-4.dat' using 3:2:4:5 with xerrorlines lt 5 title 'RK4', 'rocking-5.dat' using 3:2:4:5 with xerrorlines lt 6 title 'symplectic4', 'rocking-6.dat' using 3:2:4:5 with xerrorlines lt 7 title 'implicit Euler'
set title "rocking: error against force evaluations"
set xlabel 'force evaluations (passes over the force creators)'
set output 'order-rocking.svg'
set title "rocking: error against h (filled: fit window)"
set xlabel 'step h (s)'
plot 'rocking-0.dat' using 1:2 with linespoints lt 1 pt 6 title 'seed (slope 1.00)', 'rocking-0.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 1 pt 7 notitle, 'rocking-1.dat' using 1:2 with linespoints lt 2 pt 6 title 'explicit Euler (slope 1.01)', 'rocking-1.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 2 pt 7 notitle, 'rocking-2.dat' using 1:2 with linespoints lt 3 pt 6 title 'symplectic Euler (slope 1.00)', 'rocking-2.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 3 pt 7 notitle, 'rocking-3.dat' using 1:2 with linespoints lt 4 pt 6 title 'velocity Verlet (slope 1.00)', 'rocking-3.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 4 pt 7 notitle, 'rocking-4.dat' using 1:2 with linespoints lt 5 pt 6 title 'RK4 (slope 1.00)', 'rocking-4.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 5 pt 7 notitle, 'rocking-5.dat' using 1:2 with linespoints lt 6 pt 6 title 'symplectic4 (slope 1.00)', 'rocking-5.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 6 pt 7 notitle, 'rocking-6.dat' using 1:2 with linespoints lt 7 pt 6 title 'implicit Euler (slope 1.00)', 'rocking-6.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 7 pt 7 notitle
set output 'work-cradle3.svg'
set title "cradle3: error against CPU time (median; bars: range)"
set xlabel 'CPU time of the run (ms)'
set ylabel "velocity error / v0"
plot 'cradle3-0.dat' using 3:2:4:5 with xerrorlines lt 1 title 'seed', 'cradle3-1.dat' using 3:2:4:5 with xerrorlines lt 2 title 'explicit Euler', 'cradle3-2.dat' using 3:2:4:5 with xerrorlines lt 3 title 'symplectic Euler', 'cradle3-3.dat' using 3:2:4:5 with xerrorlines lt 4 title 'velocity Verlet', 'cradle3-4.dat' using 3:2:4:5 with xerrorlines lt 5 title 'RK4', 'cradle3-5.dat' using 3:2:4:5 with xerrorlines lt 6 title 'symplectic4', 'cradle3-6.dat' using 3:2:4:5 with xerrorlines lt 7 title 'implicit Euler'
set title "cradle3: error against force evaluations"
set xlabel 'force evaluations (passes over the force creators)'
set output 'order-cradle3.svg'
set title "cradle3: error against h (filled: fit window)"
set xlabel 'step h (s)'
plot 'cradle3-0.dat' using 1:2 with linespoints lt 1 pt 6 title 'seed (no window)', 'cradle3-0.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 1 pt 7 notitle, 'cradle3-1.dat' using 1:2 with linespoints lt 2 pt 6 title 'explicit Euler (no window)', 'cradle3-1.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 2 pt 7 notitle, 'cradle3-2.dat' using 1:2 with linespoints lt 3 pt 6 title 'symplectic Euler (no window)', 'cradle3-2.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 3 pt 7 notitle, 'cradle3-3.dat' using 1:2 with linespoints lt 4 pt 6 title 'velocity Verlet (no window)', 'cradle3-3.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 4 pt 7 notitle, 'cradle3-4.dat' using 1:2 with linespoints lt 5 pt 6 title 'RK4 (no window)', 'cradle3-4.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 5 pt 7 notitle, 'cradle3-5.dat' using 1:2 with linespoints lt 6 pt 6 title 'symplectic4 (no window)', 'cradle3-5.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 6 pt 7 notitle, 'cradle3-6.dat' using 1:2 with linespoints lt 7 pt 6 title 'implicit Euler (no window)', 'cradle3-6.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 7 pt 7 notitle
set output 'work-cradle5.svg'
set title "cradle5: error against CPU time (median; bars: range)"
set xlabel 'CPU time of the run (ms)'
set ylabel "velocity error / v0"
plot 'cradle5-0.dat' using 3:2:4:5 with xerrorlines lt 1 title 'seed', 'cradle5-1.dat' using 3:2:4:5 with xerrorlines lt 2 title 'explicit Euler', 'cradle5-2.dat' using 3:2:4:5 with xerrorlines lt 3 title 'symplectic Euler', 'cradle5-3.dat' using 3:2:4:5 with xerrorlines lt 4 title 'velocity Verlet', 'cradle5-4.dat' using 3:2:4:5 with xerrorlines lt 5 title 'RK4', 'cradle5-5.dat' using 3:2:4:5 with xerrorlines lt 6 title 'symplectic4', 'cradle5-6.dat' using 3:2:4:5 with xerrorlines lt 7 title 'implicit Euler'
set title "cradle5: error against force evaluations"
set xlabel 'force evaluations (passes over the force creators)'
set output 'order-cradle5.svg'
set title "cradle5: error against h (filled: fit window)"
set xlabel 'step h (s)'
plot 'cradle5-0.dat' using 1:2 with linespoints lt 1 pt 6 title 'seed (no window)', 'cradle5-0.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 1 pt 7 notitle, 'cradle5-1.dat' using 1:2 with linespoints lt 2 pt 6 title 'explicit Euler (no window)', 'cradle5-1.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 2 pt 7 notitle, 'cradle5-2.dat' using 1:2 with linespoints lt 3 pt 6 title 'symplectic Euler (no window)', 'cradle5-2.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 3 pt 7 notitle, 'cradle5-3.dat' using 1:2 with linespoints lt 4 pt 6 title 'velocity Verlet (no window)', 'cradle5-3.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 4 pt 7 notitle, 'cradle5-4.dat' using 1:2 with linespoints lt 5 pt 6 title 'RK4 (no window)', 'cradle5-4.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 5 pt 7 notitle, 'cradle5-5.dat' using 1:2 with linespoints lt 6 pt 6 title 'symplectic4 (no window)', 'cradle5-5.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 6 pt 7 notitle, 'cradle5-6.dat' using 1:2 with linespoints lt 7 pt 6 title 'implicit Euler (no window)', 'cradle5-6.dat' using 1:($7 > 0 ? $2 : 1/0) with points lt 7 pt 7 notitle
set output 'solver-top_drop.svg'
set title "pyramid(20): |top box drop| after 10 s (m) (labels: iterations, 0 = default)"
set xlabel 'CPU ms per step'
set ylabel "pyramid(20): |top box drop| after 10 s (m)"
plot 'solver-ours.dat' using 2:5:3:4 with xerrorlines title 'ours', 'solver-ours.dat' using 2:5:1 with labels offset 1,0.6 notitle, 'solver-chipmunk.dat' using 2:5:3:4 with xerrorlines title 'chipmunk', 'solver-chipmunk.dat' using 2:5:1 with labels offset 1,0.6 notitle, 'solver-box2d-matched.dat' using 2:5:3:4 with xerrorlines title 'box2d-matched', 'solver-box2d-matched.dat' using 2:5:1 with labels offset 1,0.6 notitle, 'solver-chipmunk-default.dat' using 2:5:3:4 with xerrorlines title 'chipmunk-default', 'solver-chipmunk-default.dat' using 2:5:1 with labels offset 1,0.6 notitle, 'solver-box2d-nosleep.dat' using 2:5:3:4 with xerrorlines title 'box2d-nosleep', 'solver-box2d-nosleep.dat' using 2:5:1 with labels offset 1,0.6 notitle, 'solver-box2d3-sse2.dat' using 2:5:3:4 with xerrorlines title 'box2d3-sse2', 'solver-box2d3-sse2.dat' using 2:5:1 with labels offset 1,0.6 notitle
set output 'solver-penetration.svg'
set title "pyramid(20): largest penetration (m) (labels: iterations, 0 = default)"
set xlabel 'CPU ms per step'
set ylabel "pyramid(20): largest penetration (m)"
plot 'solver-ours.dat' using 2:6:3:4 with xerrorlines title 'ours', 'solver-ours.dat' using 2:6:1 with labels offset 1,0.6 notitle, 'solver-chipmunk.dat' using 2:6:3:4 with xerrorlines title 'chipmunk', 'solver-chipmunk.dat' using 2:6:1 with labels offset 1,0.6 notitle, 'solver-box2d-matched.dat' using 2:6:3:4 with xerrorlines title 'box2d-matched', 'solver-box2d-matched.dat' using 2:6:1 with labels offset 1,0.6 notitle, 'solver-chipmunk-default.dat' using 2:6:3:4 with xerrorlines title 'chipmunk-default', 'solver-chipmunk-default.dat' using 2:6:1 with labels offset 1,0.6 notitle, 'solver-box2d-nosleep.dat' using 2:6:3:4 with xerrorlines title 'box2d-nosleep', 'solver-box2d-nosleep.dat' using 2:6:1 with labels offset 1,0.6 notitle, 'solver-box2d3-sse2.dat' using 2:6:3:4 with xerrorlines title 'box2d3-sse2', 'solver-box2d3-sse2.dat' using 2:6:1 with labels offset 1,0.6 notitle
set output 'solver-drift.svg'
set title "column(10): |top box sideways drift| (m) (labels: iterations, 0 = default)"
set xlabel 'CPU ms per step'
set ylabel "column(10): |top box sideways drift| (m)"
plot 'solver-ours.dat' using 7:10:8:9 with xerrorlines title 'ours', 'solver-ours.dat' using 7:10:1 with labels offset 1,0.6 notitle, 'solver-chipmunk.dat' using 7:10:8:9 with xerrorlines title 'chipmunk', 'solver-chipmunk.dat' using 7:10:1 with labels offset 1,0.6 notitle, 'solver-box2d-matched.dat' using 7:10:8:9 with xerrorlines title 'box2d-matched', 'solver-box2d-matched.dat' using 7:10:1 with labels offset 1,0.6 notitle, 'solver-chipmunk-default.dat' using 7:10:8:9 with xerrorlines title 'chipmunk-default', 'solver-chipmunk-default.dat' using 7:10:1 with labels offset 1,0.6 notitle, 'solver-box2d-nosleep.dat' using 7:10:8:9 with xerrorlines title 'box2d-nosleep', 'solver-box2d-nosleep.dat' using 7:10:1 with labels offset 1,0.6 notitle, 'solver-box2d3-sse2.dat' using 7:10:8:9 with xerrorlines title 'box2d3-sse2', 'solver-box2d3-sse2.dat' using 7:10:1 with labels offset 1,0.6 notitle
