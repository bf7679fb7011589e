%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE ZC_CHK140
    ! zerocal robot program: a check of the offsets entered after a calibration session.
    ! Robot ABB IRB 140T-6/0.81 (IRB 140T; ROS-I model irb140t_6_81) (profile abb-irb140); 5 of the
    ! session plan's 24 poses (4, 7, 9, 10, 17), at the session's commanded angles. Written by zerocal
    ! 0.1.0.
    ! Every pose is captured twice: first with every joint arriving moving positive (from 1 deg
    ! below), then, after every joint has gone 4 deg past it, moving negative (from above). The
    ! pendant averages the two: the middle of every gear's backlash.
    ! Before it: stage 0 on the bench (the pendant's check mode starts there). Stop: clip the pendant
    ! to the flange (the robot stands with the pendant tilted past its range, so it cannot capture
    ! early). Then the check's poses in the plan's order, twice each; the pendant must hold the same
    ! plan as the session (plan set). No stage 1.
    ! Closing reversal: the robot parks where the pendant went on the flange and stops; take the
    ! pendant off and reverse it on the bench as in stage 0 (two readings, turned 180 deg on the same
    ! spot between them). The program ends there.
    ! Speed: joint moves at 10 % of each joint's maximum speed, exact stops.
    ! Dwell 3.1 s at each capture: settling 1 s (stated default) + the pendant's 2 s still window + 2
    ! sensor periods of 0.05 s.
    ! Predicted robot time 3.4 min, the closing reversal included: motion 39 s, dwell 37 s (12
    ! captures), 2 mountings 120 s, operator OKs 10 s.
    ! WARNING: the path is NOT checked for collisions with the cell, the pendant or its bracket. Check
    ! the cell, then step through the program once at reduced speed (T1) before running it.
    CONST jointtarget zc_t1:=[[-90.00000,-45.00000,-61.92496,-34.04074,-111.09156,-10.96417],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t2:=[[-91.00000,-1.00000,-62.92496,-35.04074,-112.09156,-11.96417],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t3:=[[-90.00000,0.00000,-61.92496,-34.04074,-111.09156,-10.96417],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t4:=[[-86.00000,4.00000,-57.92496,-30.04074,-107.09156,-6.96417],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t5:=[[-90.00000,0.00000,-61.92496,-34.04074,-111.09156,-10.96417],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t6:=[[-91.00000,-1.00000,-109.86448,-175.83403,-111.48146,-359.90647],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t7:=[[-90.00000,0.00000,-108.86448,-174.83403,-110.48146,-358.90647],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t8:=[[-86.00000,4.00000,-104.86448,-170.83403,-106.48146,-354.90647],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t9:=[[-90.00000,0.00000,-108.86448,-174.83403,-110.48146,-358.90647],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t10:=[[-91.00000,-1.00000,-181.91020,-91.14159,-105.07792,-269.28151],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t11:=[[-90.00000,0.00000,-180.91020,-90.14159,-104.07792,-268.28151],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t12:=[[-86.00000,4.00000,-176.91020,-86.14159,-100.07792,-264.28151],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t13:=[[-90.00000,0.00000,-180.91020,-90.14159,-104.07792,-268.28151],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t14:=[[-91.00000,-1.00000,-155.05227,-0.01433,-21.42826,-365.90509],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t15:=[[-90.00000,0.00000,-154.05227,0.98567,-20.42826,-364.90509],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t16:=[[-86.00000,4.00000,-150.05227,4.98567,-16.42826,-360.90509],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t17:=[[-90.00000,0.00000,-154.05227,0.98567,-20.42826,-364.90509],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t18:=[[-91.00000,-1.00000,-159.16154,-157.46015,21.17470,158.26824],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t19:=[[-90.00000,0.00000,-158.16154,-156.46015,22.17470,159.26824],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t20:=[[-86.00000,4.00000,-154.16154,-152.46015,26.17470,163.26824],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t21:=[[-90.00000,0.00000,-158.16154,-156.46015,22.17470,159.26824],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t22:=[[-90.00000,-45.00000,-61.92496,-34.04074,-111.09156,-10.96417],[9E9,9E9,9E9,9E9,9E9,9E9]];
    PROC main()
        ! zerocal check: the pendant goes on the flange here, tilted past its range so that it cannot
        ! capture yet
        ! from wherever the robot stands: speeddata v100, step through it
        MoveAbsJ zc_t1,v100,fine,tool0;
        TPWrite "zerocal: clip the pendant to the flange";
        TPWrite "(its screen at POSE 1), then continue.";
        STOP;
        ! zerocal check: pose 4 of 24, captured from below, then from above
        MoveAbsJ zc_t2,v100 \T:=2.124,fine,tool0;
        MoveAbsJ zc_t3,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t4,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t5,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 7 of 24, captured from below, then from above
        MoveAbsJ zc_t6,v100 \T:=8.409,fine,tool0;
        MoveAbsJ zc_t7,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t8,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t9,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 9 of 24, captured from below, then from above
        MoveAbsJ zc_t10,v100 \T:=3.188,fine,tool0;
        MoveAbsJ zc_t11,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t12,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t13,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 10 of 24, captured from below, then from above
        MoveAbsJ zc_t14,v100 \T:=3.027,fine,tool0;
        MoveAbsJ zc_t15,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t16,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t17,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 17 of 24, captured from below, then from above
        MoveAbsJ zc_t18,v100 \T:=12.281,fine,tool0;
        MoveAbsJ zc_t19,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t20,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t21,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal: the check's poses done; the robot parks where the pendant went on the flange (tilted
        ! past its range) for the closing reversal
        MoveAbsJ zc_t22,v100 \T:=4.437,fine,tool0;
        TPWrite "zerocal: closing reversal: take the";
        TPWrite "pendant off the flange to the bench of";
        TPWrite "stage 0, let it capture, turn it 180 deg";
        TPWrite "on the same spot, press OK, let it";
        TPWrite "capture. Then continue.";
        STOP;
        ! zerocal: check done; export it from the pendant (zerocal pendant export), then zerocal check
    ENDPROC
ENDMODULE
