%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE ZC_CHK140
    ! zerocal robot program: a check of the offsets entered after a calibration session.
    ! Robot ABB IRB 140T-6/0.81 (IRB 140T; ROS-I model irb140t_6_81) (profile abb-irb140); 5 of the
    ! session plan's 43 poses (1, 9, 10, 19, 22), at the session's commanded angles. Written by
    ! zerocal 0.1.0.
    ! Every pose is captured twice: first with every joint arriving moving positive (from 1 deg
    ! below), then, after every joint has gone 4 deg past it, moving negative (from above). The
    ! pendant averages the two: the middle of every gear's backlash.
    ! Before it: stage 0 on the bench (the pendant's check mode starts there). Stop: clip the pendant
    ! to the flange (the robot stands with the pendant tilted past its range, so it cannot capture
    ! early). Then the check's poses in the plan's order, twice each; the pendant must hold the same
    ! plan as the session (plan set). No stage 1.
    ! Closing bench readings: the robot parks where the pendant went on the flange and stops; take the
    ! pendant off and continue: the program ends there and the robot is free. Then read the pendant on
    ! the bench as in stage 0 (4 headings, turned by hand about a quarter turn on the same spot
    ! between them).
    ! Speed: joint moves at 10 % of each joint's maximum speed, exact stops.
    ! Dwell 3.1 s at each capture: settling 1 s (stated default) + the pendant's 2 s still window + 2
    ! sensor periods of 0.05 s.
    ! Predicted robot time 3.1 min, until the pendant is off the flange: motion 32 s, dwell 31 s (10
    ! captures), 2 mountings 120 s, operator OKs 0 s; then the closing bench readings, 42 s, the robot
    ! free.
    ! WARNING: the path is NOT checked for collisions with the cell, the pendant or its bracket. Check
    ! the cell, then step through the program once at reduced speed (T1) before running it.
    CONST jointtarget zc_t1:=[[-90.00000,-45.00000,-161.68633,-175.70261,16.04062,-178.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t2:=[[-91.00000,-8.20970,-162.68633,-176.70261,15.04062,-179.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t3:=[[-90.00000,-7.20970,-161.68633,-175.70261,16.04062,-178.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t4:=[[-86.00000,-3.20970,-157.68633,-171.70261,20.04062,-174.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t5:=[[-90.00000,-7.20970,-161.68633,-175.70261,16.04062,-178.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t6:=[[-91.00000,-65.94064,3.26665,-37.33598,-114.58650,-17.28775],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t7:=[[-90.00000,-64.94064,4.26665,-36.33598,-113.58650,-16.28775],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t8:=[[-86.00000,-60.94064,8.26665,-32.33598,-109.58650,-12.28775],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t9:=[[-90.00000,-64.94064,4.26665,-36.33598,-113.58650,-16.28775],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t10:=[[-91.00000,-74.61238,6.62156,-8.86412,-109.11995,-7.91099],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t11:=[[-90.00000,-73.61238,7.62156,-7.86412,-108.11995,-6.91099],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t12:=[[-86.00000,-69.61238,11.62156,-3.86412,-104.11995,-2.91099],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t13:=[[-90.00000,-73.61238,7.62156,-7.86412,-108.11995,-6.91099],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t14:=[[-91.00000,59.53654,-87.55478,163.87932,-21.89299,16.67723],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t15:=[[-90.00000,60.53654,-86.55478,164.87932,-20.89299,17.67723],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t16:=[[-86.00000,64.53654,-82.55478,168.87932,-16.89299,21.67723],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t17:=[[-90.00000,60.53654,-86.55478,164.87932,-20.89299,17.67723],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t18:=[[-91.00000,28.20450,-54.19616,80.36859,-111.11344,66.50680],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t19:=[[-90.00000,29.20450,-53.19616,81.36859,-110.11344,67.50680],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t20:=[[-86.00000,33.20450,-49.19616,85.36859,-106.11344,71.50680],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t21:=[[-90.00000,29.20450,-53.19616,81.36859,-110.11344,67.50680],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t22:=[[-90.00000,-45.00000,-161.68633,-175.70261,16.04062,-178.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    PROC main()
        ! zerocal check: the pendant goes on the flange here, tilted past its range so that it cannot
        ! capture yet
        ! from wherever the robot stands: speeddata v100, step through it
        MoveAbsJ zc_t1,v100,fine,tool0;
        TPWrite "zerocal: clip the pendant to the flange";
        TPWrite "(its screen at POSE 1), then continue.";
        STOP;
        ! zerocal check: pose 1 of 43, captured from below, then from above
        MoveAbsJ zc_t2,v100 \T:=1.835,fine,tool0;
        MoveAbsJ zc_t3,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t4,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t5,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 9 of 43, captured from below, then from above
        MoveAbsJ zc_t6,v100 \T:=6.723,fine,tool0;
        MoveAbsJ zc_t7,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t8,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t9,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 10 of 43, captured from below, then from above
        MoveAbsJ zc_t10,v100 \T:=1.287,fine,tool0;
        MoveAbsJ zc_t11,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t12,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t13,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 19 of 43, captured from below, then from above
        MoveAbsJ zc_t14,v100 \T:=5.690,fine,tool0;
        MoveAbsJ zc_t15,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t16,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t17,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 22 of 43, captured from below, then from above
        MoveAbsJ zc_t18,v100 \T:=3.030,fine,tool0;
        MoveAbsJ zc_t19,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t20,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t21,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal: the check's poses done; the robot parks where the pendant went on the flange (tilted
        ! past its range) to take the pendant off
        MoveAbsJ zc_t22,v100 \T:=7.664,fine,tool0;
        TPWrite "zerocal: take the pendant off the";
        TPWrite "flange, then continue: the program ends";
        TPWrite "and the robot is free. On the bench of";
        TPWrite "stage 0, read the pendant at its 4";
        TPWrite "headings as it guides (the closing bench";
        TPWrite "readings).";
        STOP;
        ! zerocal: the robot's part of the check is done; after the closing bench readings, export it from
        ! the pendant (zerocal pendant export), then zerocal check
    ENDPROC
ENDMODULE
