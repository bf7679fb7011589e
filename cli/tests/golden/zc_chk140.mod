%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE ZC_CHK140
    ! zerocal robot program: a check of the offsets entered after a calibration session.
    ! Robot ABB IRB 140T-6/0.81 (IRB 140T; ROS-I model irb140t_6_81) (profile abb-irb140); 5 of the
    ! session plan's 43 poses (29, 30, 32, 33, 34), at the session's commanded angles. Written by
    ! zerocal 0.1.0.
    ! Every pose is captured twice: first with every joint arriving moving positive (from 1 deg
    ! below), then, after every joint has gone 4 deg past it, moving negative (from above). The
    ! pendant averages the two: the middle of every gear's backlash.
    ! Before it: stage 0 on the bench (the pendant's check mode starts there). Stop: clip the pendant
    ! to the flange (the robot stands with the pendant tilted past its range, so it cannot capture
    ! early). Then the check's poses in the plan's order, twice each; the pendant must hold the same
    ! plan as the session (plan set). No stage 1.
    ! Closing bench readings: the robot parks where the pendant went on the flange and stops; take the
    ! pendant off and read it on the bench as in stage 0 (4 headings, turned by hand about a quarter
    ! turn on the same spot between them). The program ends there.
    ! Speed: joint moves at 10 % of each joint's maximum speed, exact stops.
    ! Dwell 3.1 s at each capture: settling 1 s (stated default) + the pendant's 2 s still window + 2
    ! sensor periods of 0.05 s.
    ! Predicted robot time 3.6 min, the closing bench readings included: motion 25 s, dwell 43 s (14
    ! captures), 2 mountings 120 s, operator OKs 30 s.
    ! WARNING: the path is NOT checked for collisions with the cell, the pendant or its bracket. Check
    ! the cell, then step through the program once at reduced speed (T1) before running it.
    CONST jointtarget zc_t1:=[[-90.00000,-45.00000,12.64060,-179.73941,12.18260,-1.05352],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t2:=[[-91.00000,0.00993,11.64060,-180.73941,11.18260,-2.05352],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t3:=[[-90.00000,1.00993,12.64060,-179.73941,12.18260,-1.05352],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t4:=[[-86.00000,5.00993,16.64060,-175.73941,16.18260,2.94648],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t5:=[[-90.00000,1.00993,12.64060,-179.73941,12.18260,-1.05352],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t6:=[[-91.00000,30.98035,-0.93392,-76.03986,105.68180,-60.43634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t7:=[[-90.00000,31.98035,0.06608,-75.03986,106.68180,-59.43634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t8:=[[-86.00000,35.98035,4.06608,-71.03986,110.68180,-55.43634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t9:=[[-90.00000,31.98035,0.06608,-75.03986,106.68180,-59.43634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t10:=[[-91.00000,-60.46594,14.64967,-105.55880,108.69512,-137.86105],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t11:=[[-90.00000,-59.46594,15.64967,-104.55880,109.69512,-136.86105],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t12:=[[-86.00000,-55.46594,19.64967,-100.55880,113.69512,-132.86105],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t13:=[[-90.00000,-59.46594,15.64967,-104.55880,109.69512,-136.86105],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t14:=[[-91.00000,-64.76999,10.34112,-36.38991,52.85930,-157.73882],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t15:=[[-90.00000,-63.76999,11.34112,-35.38991,53.85930,-156.73882],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t16:=[[-86.00000,-59.76999,15.34112,-31.38991,57.85930,-152.73882],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t17:=[[-90.00000,-63.76999,11.34112,-35.38991,53.85930,-156.73882],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t18:=[[-91.00000,-75.24934,15.76834,-10.29502,55.04352,-177.04119],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t19:=[[-90.00000,-74.24934,16.76834,-9.29502,56.04352,-176.04119],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t20:=[[-86.00000,-70.24934,20.76834,-5.29502,60.04352,-172.04119],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t21:=[[-90.00000,-74.24934,16.76834,-9.29502,56.04352,-176.04119],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t22:=[[-90.00000,-45.00000,12.64060,-179.73941,12.18260,-1.05352],[9E9,9E9,9E9,9E9,9E9,9E9]];
    PROC main()
        ! zerocal check: the pendant goes on the flange here, tilted past its range so that it cannot
        ! capture yet
        ! from wherever the robot stands: speeddata v100, step through it
        MoveAbsJ zc_t1,v100,fine,tool0;
        TPWrite "zerocal: clip the pendant to the flange";
        TPWrite "(its screen at POSE 1), then continue.";
        STOP;
        ! zerocal check: pose 29 of 43, captured from below, then from above
        MoveAbsJ zc_t2,v100 \T:=2.164,fine,tool0;
        MoveAbsJ zc_t3,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t4,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t5,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 30 of 43, captured from below, then from above
        MoveAbsJ zc_t6,v100 \T:=3.404,fine,tool0;
        MoveAbsJ zc_t7,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t8,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t9,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 32 of 43, captured from below, then from above
        MoveAbsJ zc_t10,v100 \T:=4.061,fine,tool0;
        MoveAbsJ zc_t11,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t12,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t13,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 33 of 43, captured from below, then from above
        MoveAbsJ zc_t14,v100 \T:=2.417,fine,tool0;
        MoveAbsJ zc_t15,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t16,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t17,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 34 of 43, captured from below, then from above
        MoveAbsJ zc_t18,v100 \T:=1.221,fine,tool0;
        MoveAbsJ zc_t19,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t20,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t21,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal: the check's poses done; the robot parks where the pendant went on the flange (tilted
        ! past its range) for the closing bench readings
        MoveAbsJ zc_t22,v100 \T:=5.258,fine,tool0;
        TPWrite "zerocal: closing bench readings: take";
        TPWrite "the pendant off the flange to the bench";
        TPWrite "of stage 0 and read it at 4 headings,";
        TPWrite "turned by hand about a quarter turn on";
        TPWrite "the same spot between them, as the";
        TPWrite "pendant guides. Then continue.";
        STOP;
        ! zerocal: check done; export it from the pendant (zerocal pendant export), then zerocal check
    ENDPROC
ENDMODULE
