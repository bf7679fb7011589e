%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE ZC_CHK140
    ! zerocal robot program: a check of the offsets entered after a calibration session.
    ! Robot ABB IRB 140T-6/0.81 (IRB 140T; ROS-I model irb140t_6_81) (profile abb-irb140); 5 of the
    ! session plan's 43 poses (2, 4, 20, 27, 30), at the session's commanded angles. Written by
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
    ! Predicted robot time 3.0 min, until the pendant is off the flange: motion 29 s, dwell 31 s (10
    ! captures), 2 mountings 120 s, operator OKs 0 s; then the closing bench readings, 42 s, the robot
    ! free.
    ! WARNING: the path is NOT checked for collisions with the cell, the pendant or its bracket. Check
    ! the cell, then step through the program once at reduced speed (T1) before running it.
    CONST jointtarget zc_t1:=[[-90.00000,-45.00000,-175.46637,-3.30253,2.63117,-2.56084],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t2:=[[-91.00000,-4.65398,-176.46637,-4.30253,1.63117,-3.56084],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t3:=[[-90.00000,-3.65398,-175.46637,-3.30253,2.63117,-2.56084],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t4:=[[-86.00000,0.34602,-171.46637,0.69747,6.63117,1.43916],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t5:=[[-90.00000,-3.65398,-175.46637,-3.30253,2.63117,-2.56084],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t6:=[[-91.00000,25.14421,-225.45690,19.26224,23.62779,-21.21176],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t7:=[[-90.00000,26.14421,-224.45690,20.26224,24.62779,-20.21176],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t8:=[[-86.00000,30.14421,-220.45690,24.26224,28.62779,-16.21176],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t9:=[[-90.00000,26.14421,-224.45690,20.26224,24.62779,-20.21176],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t10:=[[-91.00000,-59.52567,-115.20023,-81.58773,-10.81286,81.33545],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t11:=[[-90.00000,-58.52567,-114.20023,-80.58773,-9.81286,82.33545],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t12:=[[-86.00000,-54.52567,-110.20023,-76.58773,-5.81286,86.33545],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t13:=[[-90.00000,-58.52567,-114.20023,-80.58773,-9.81286,82.33545],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t14:=[[-91.00000,62.83020,-203.83282,35.43364,-54.71690,-33.00528],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t15:=[[-90.00000,63.83020,-202.83282,36.43364,-53.71690,-32.00528],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t16:=[[-86.00000,67.83020,-198.83282,40.43364,-49.71690,-28.00528],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t17:=[[-90.00000,63.83020,-202.83282,36.43364,-53.71690,-32.00528],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t18:=[[-91.00000,-35.30281,-95.66632,-123.42933,-112.62784,30.85351],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t19:=[[-90.00000,-34.30281,-94.66632,-122.42933,-111.62784,31.85351],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t20:=[[-86.00000,-30.30281,-90.66632,-118.42933,-107.62784,35.85351],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t21:=[[-90.00000,-34.30281,-94.66632,-122.42933,-111.62784,31.85351],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t22:=[[-90.00000,-45.00000,-175.46637,-3.30253,2.63117,-2.56084],[9E9,9E9,9E9,9E9,9E9,9E9]];
    PROC main()
        ! zerocal check: the pendant goes on the flange here, tilted past its range so that it cannot
        ! capture yet
        ! from wherever the robot stands: speeddata v100, step through it
        MoveAbsJ zc_t1,v100,fine,tool0;
        TPWrite "zerocal: clip the pendant to the flange";
        TPWrite "(its screen at POSE 1), then continue.";
        STOP;
        ! zerocal check: pose 2 of 43, captured from below, then from above
        MoveAbsJ zc_t2,v100 \T:=1.977,fine,tool0;
        MoveAbsJ zc_t3,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t4,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t5,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 4 of 43, captured from below, then from above
        MoveAbsJ zc_t6,v100 \T:=2.301,fine,tool0;
        MoveAbsJ zc_t7,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t8,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t9,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 20 of 43, captured from below, then from above
        MoveAbsJ zc_t10,v100 \T:=4.580,fine,tool0;
        MoveAbsJ zc_t11,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t12,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t13,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 27 of 43, captured from below, then from above
        MoveAbsJ zc_t14,v100 \T:=5.218,fine,tool0;
        MoveAbsJ zc_t15,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t16,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t17,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 30 of 43, captured from below, then from above
        MoveAbsJ zc_t18,v100 \T:=4.964,fine,tool0;
        MoveAbsJ zc_t19,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t20,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t21,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal: the check's poses done; the robot parks where the pendant went on the flange (tilted
        ! past its range) to take the pendant off
        MoveAbsJ zc_t22,v100 \T:=3.833,fine,tool0;
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
