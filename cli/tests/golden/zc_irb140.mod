%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE ZC_IRB140
    ! zerocal robot program: a joint-zero calibration session.
    ! Robot ABB IRB 140T-6/0.81 (IRB 140T; ROS-I model irb140t_6_81) (profile abb-irb140); 24 stage-2
    ! poses. Written by zerocal 0.1.0; targets in the controller's joint degrees.
    ! Stop: clip the pendant to the upper arm (the robot stands with the pendant tilted past its
    ! range, so it cannot capture early). Stage 1: the stage-1 pose, then joint 1 turned by 180 deg
    ! (an OK on the pendant takes that reading). Stop: joint 1 back, clip the pendant to the flange
    ! (tilted again). Stage 2: the plan's poses in its order; load the same plan into the pendant
    ! (plan set).
    ! Speed: joint moves at 10 % of each joint's maximum speed, exact stops. Backlash: every target is
    ! reached with each joint moving J1+ J2+ J3+ J4+ J5- J6-.
    ! Dwell 3.1 s at each capture: settling 1 s (stated default) + the pendant's 2 s still window + 2
    ! sensor periods.
    ! Predicted robot time 5.4 min (motion 111 s, dwell 81 s, remount 120 s, operator OKs 10 s).
    ! WARNING: the path is NOT checked for collisions with the cell, the pendant or its bracket. Check
    ! the cell, then step through the program once at reduced speed (T1) before running it.
    CONST jointtarget zc_t1:=[[-91.00000,-46.00000,-91.00000,-1.00000,1.00000,1.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t2:=[[-90.00000,-45.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t3:=[[-90.00000,0.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t4:=[[90.00000,0.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t5:=[[-91.00000,0.00000,-17.24796,-96.78035,-101.14702,-116.03872],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t6:=[[-90.00000,0.00000,-17.24796,-95.78035,-101.14702,-116.03872],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t7:=[[-90.00000,0.00000,27.75204,-95.78035,-101.14702,-116.03872],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t8:=[[-90.00000,0.00000,9.34017,-174.96593,11.90847,-5.32973],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t9:=[[-90.00000,0.00000,10.34017,-173.96593,10.90847,-6.32973],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t10:=[[-90.00000,0.00000,47.85089,-117.08203,-114.31798,217.44832],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t11:=[[-90.00000,0.00000,47.85089,-117.08203,-114.31798,216.44832],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t12:=[[-90.00000,0.00000,-38.45207,-2.90447,36.54074,184.39434],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t13:=[[-90.00000,0.00000,-37.45207,-2.90447,35.54074,184.39434],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t14:=[[-90.00000,0.00000,43.21657,-72.10469,111.77749,314.62760],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t15:=[[-90.00000,0.00000,43.21657,-71.10469,110.77749,313.62760],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t16:=[[-90.00000,0.00000,-68.16156,129.56635,111.82786,161.59757],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t17:=[[-90.00000,0.00000,-67.16156,129.56635,110.82786,161.59757],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t18:=[[-90.00000,0.00000,-143.36343,87.55256,84.54316,225.95293],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t19:=[[-90.00000,0.00000,-142.36343,88.55256,84.54316,224.95293],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t20:=[[-90.00000,0.00000,-210.08119,50.96740,44.70794,317.44251],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t21:=[[-90.00000,0.00000,-209.08119,51.96740,44.70794,316.44251],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t22:=[[-90.00000,0.00000,-190.51155,-29.69813,14.32819,392.43319],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t23:=[[-90.00000,0.00000,-190.51155,-28.69813,14.32819,391.43319],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t24:=[[-90.00000,0.00000,-152.18140,104.62146,-111.96481,298.49844],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t25:=[[-90.00000,0.00000,-102.90694,194.61726,-101.22002,3.52495],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t26:=[[-90.00000,0.00000,-102.90694,194.61726,-102.22002,3.52495],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t27:=[[-90.00000,0.00000,-115.40342,133.52800,-106.47603,-17.22632],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t28:=[[-90.00000,0.00000,-114.40342,134.52800,-106.47603,-17.22632],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t29:=[[-90.00000,0.00000,-159.05854,82.74943,-60.50261,-74.79644],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t30:=[[-90.00000,0.00000,-158.05854,83.74943,-61.50261,-74.79644],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t31:=[[-90.00000,0.00000,-219.96282,167.27133,-39.49869,-165.76418],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t32:=[[-90.00000,0.00000,-218.96282,167.27133,-40.49869,-165.76418],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t33:=[[-90.00000,0.00000,-164.00855,144.23296,21.25469,-148.65343],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t34:=[[-90.00000,0.00000,-164.00855,145.23296,20.25469,-149.65343],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t35:=[[-90.00000,0.00000,-112.16869,65.99251,103.02787,-158.83474],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t36:=[[-90.00000,0.00000,-112.16869,66.99251,102.02787,-158.83474],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t37:=[[-90.00000,0.00000,-98.96408,6.34233,101.38964,-181.57480],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t38:=[[-90.00000,0.00000,-98.96408,7.34233,101.38964,-181.57480],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t39:=[[-90.00000,0.00000,-25.66353,148.51094,-27.40497,-332.55282],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t40:=[[-90.00000,0.00000,-30.01506,80.92512,-110.31498,-298.17294],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t41:=[[-90.00000,0.00000,-29.01506,81.92512,-110.31498,-299.17294],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t42:=[[-90.00000,0.00000,-71.15342,18.22845,-105.76483,-349.23925],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t43:=[[-90.00000,0.00000,-70.15342,19.22845,-106.76483,-349.23925],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t44:=[[-90.00000,0.00000,-46.22883,-73.20478,-109.19206,-399.34010],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t45:=[[-90.00000,0.00000,-46.22883,-72.20478,-109.19206,-399.34010],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t46:=[[-90.00000,0.00000,0.30015,-139.76500,-7.65313,-392.84274],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t47:=[[-90.00000,0.00000,0.30015,-138.76500,-8.65313,-393.84274],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t48:=[[-90.00000,0.00000,-183.38631,-24.09578,-3.76432,-341.34354],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t49:=[[-90.00000,0.00000,-182.38631,-24.09578,-4.76432,-342.34354],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t50:=[[-90.00000,0.00000,-213.43986,-82.83680,-113.73258,-228.76975],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t51:=[[-90.00000,0.00000,-212.43986,-81.83680,-113.73258,-229.76975],[9E9,9E9,9E9,9E9,9E9,9E9]];
    PROC main()
        ! zerocal stage 1: the pendant goes on the upper arm here, tilted past its range so that it cannot
        ! capture yet
        ! from wherever the robot stands: speeddata v100, step through it
        MoveAbsJ zc_t1,v100,fine,tool0;
        MoveAbsJ zc_t2,v100 \T:=0.241,fine,tool0;
        TPWrite "zerocal: clip the pendant to the upper";
        TPWrite "arm (its screen at STAGE 1), then";
        TPWrite "continue.";
        STOP;
        MoveAbsJ zc_t3,v100 \T:=2.164,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 1: joint 1 turned by 180 deg
        MoveAbsJ zc_t4,v100 \T:=7.564,fine,tool0;
        WaitTime 3.100;
        TPWrite "zerocal: press OK on the pendant, wait";
        TPWrite "for its POSE screen, then continue.";
        STOP;
        ! zerocal: joint 1 back; the pendant goes on the flange here, tilted past its range
        MoveAbsJ zc_t5,v100 \T:=7.604,fine,tool0;
        MoveAbsJ zc_t6,v100 \T:=0.241,fine,tool0;
        TPWrite "zerocal: clip the pendant to the flange";
        TPWrite "(its screen at POSE 1), then continue.";
        STOP;
        ! zerocal stage 2: pose 1 of 24
        MoveAbsJ zc_t7,v100 \T:=2.109,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 2 of 24
        MoveAbsJ zc_t8,v100 \T:=3.664,fine,tool0;
        MoveAbsJ zc_t9,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 3 of 24
        MoveAbsJ zc_t10,v100 \T:=5.627,fine,tool0;
        MoveAbsJ zc_t11,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 4 of 24
        MoveAbsJ zc_t12,v100 \T:=4.714,fine,tool0;
        MoveAbsJ zc_t13,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 5 of 24
        MoveAbsJ zc_t14,v100 \T:=3.549,fine,tool0;
        MoveAbsJ zc_t15,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 6 of 24
        MoveAbsJ zc_t16,v100 \T:=6.098,fine,tool0;
        MoveAbsJ zc_t17,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 7 of 24
        MoveAbsJ zc_t18,v100 \T:=3.309,fine,tool0;
        MoveAbsJ zc_t19,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 8 of 24
        MoveAbsJ zc_t20,v100 \T:=2.983,fine,tool0;
        MoveAbsJ zc_t21,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 9 of 24
        MoveAbsJ zc_t22,v100 \T:=2.792,fine,tool0;
        MoveAbsJ zc_t23,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 10 of 24
        MoveAbsJ zc_t24,v100 \T:=4.227,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 11 of 24
        MoveAbsJ zc_t25,v100 \T:=7.209,fine,tool0;
        MoveAbsJ zc_t26,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 12 of 24
        MoveAbsJ zc_t27,v100 \T:=2.221,fine,tool0;
        MoveAbsJ zc_t28,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 13 of 24
        MoveAbsJ zc_t29,v100 \T:=2.096,fine,tool0;
        MoveAbsJ zc_t30,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 14 of 24
        MoveAbsJ zc_t31,v100 \T:=2.844,fine,tool0;
        MoveAbsJ zc_t32,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 15 of 24
        MoveAbsJ zc_t33,v100 \T:=2.492,fine,tool0;
        MoveAbsJ zc_t34,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 16 of 24
        MoveAbsJ zc_t35,v100 \T:=2.823,fine,tool0;
        MoveAbsJ zc_t36,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 17 of 24
        MoveAbsJ zc_t37,v100 \T:=2.208,fine,tool0;
        MoveAbsJ zc_t38,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 18 of 24
        MoveAbsJ zc_t39,v100 \T:=4.445,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 19 of 24
        MoveAbsJ zc_t40,v100 \T:=2.827,fine,tool0;
        MoveAbsJ zc_t41,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 20 of 24
        MoveAbsJ zc_t42,v100 \T:=2.293,fine,tool0;
        MoveAbsJ zc_t43,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 21 of 24
        MoveAbsJ zc_t44,v100 \T:=3.091,fine,tool0;
        MoveAbsJ zc_t45,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 22 of 24
        MoveAbsJ zc_t46,v100 \T:=3.344,fine,tool0;
        MoveAbsJ zc_t47,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 23 of 24
        MoveAbsJ zc_t48,v100 \T:=7.443,fine,tool0;
        MoveAbsJ zc_t49,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 24 of 24
        MoveAbsJ zc_t50,v100 \T:=3.550,fine,tool0;
        MoveAbsJ zc_t51,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        ! zerocal: session done; the pendant shows the result
    ENDPROC
ENDMODULE
