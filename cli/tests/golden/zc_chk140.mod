%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE ZC_CHK140
    ! zerocal robot program: a check of the offsets entered after a calibration session.
    ! Robot ABB IRB 140T-6/0.81 (IRB 140T; ROS-I model irb140t_6_81) (profile abb-irb140); 5 of the
    ! session plan's 43 poses (1, 23, 24, 25, 39), at the session's commanded angles. Written by
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
    ! Predicted robot time 2.9 min, until the pendant is off the flange: motion 25 s, dwell 31 s (10
    ! captures), 2 mountings 120 s, operator OKs 0 s; then the closing bench readings, 42 s, the robot
    ! free.
    ! WARNING: the path is NOT checked for collisions with the cell, the pendant or its bracket. Check
    ! the cell, then step through the program once at reduced speed (T1) before running it.
    CONST jointtarget zc_t1:=[[-90.00000,-45.00000,-161.68633,184.29739,16.04062,-178.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t2:=[[-91.00000,-8.20970,-162.68633,183.29739,15.04062,-179.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t3:=[[-90.00000,-7.20970,-161.68633,184.29739,16.04062,-178.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t4:=[[-86.00000,-3.20970,-157.68633,188.29739,20.04062,-174.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t5:=[[-90.00000,-7.20970,-161.68633,184.29739,16.04062,-178.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t6:=[[-91.00000,-62.50998,-114.02744,103.28639,15.33454,-111.56189],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t7:=[[-90.00000,-61.50998,-113.02744,104.28639,16.33454,-110.56189],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t8:=[[-86.00000,-57.50998,-109.02744,108.28639,20.33454,-106.56189],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t9:=[[-90.00000,-61.50998,-113.02744,104.28639,16.33454,-110.56189],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t10:=[[-91.00000,-36.60594,-146.67123,148.22613,3.66348,-154.79671],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t11:=[[-90.00000,-35.60594,-145.67123,149.22613,4.66348,-153.79671],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t12:=[[-86.00000,-31.60594,-141.67123,153.22613,8.66348,-149.79671],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t13:=[[-90.00000,-35.60594,-145.67123,149.22613,4.66348,-153.79671],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t14:=[[-91.00000,-3.00218,-173.84120,70.40369,-22.62188,-69.54098],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t15:=[[-90.00000,-2.00218,-172.84120,71.40369,-21.62188,-68.54098],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t16:=[[-86.00000,1.99782,-168.84120,75.40369,-17.62188,-64.54098],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t17:=[[-90.00000,-2.00218,-172.84120,71.40369,-21.62188,-68.54098],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t18:=[[-91.00000,-35.21276,-80.97191,11.42044,107.45177,-172.58634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t19:=[[-90.00000,-34.21276,-79.97191,12.42044,108.45177,-171.58634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t20:=[[-86.00000,-30.21276,-75.97191,16.42044,112.45177,-167.58634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t21:=[[-90.00000,-34.21276,-79.97191,12.42044,108.45177,-171.58634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t22:=[[-90.00000,-45.00000,-161.68633,184.29739,16.04062,-178.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
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
        ! zerocal check: pose 23 of 43, captured from below, then from above
        MoveAbsJ zc_t6,v100 \T:=2.774,fine,tool0;
        MoveAbsJ zc_t7,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t8,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t9,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 24 of 43, captured from below, then from above
        MoveAbsJ zc_t10,v100 \T:=1.744,fine,tool0;
        MoveAbsJ zc_t11,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t12,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t13,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 25 of 43, captured from below, then from above
        MoveAbsJ zc_t14,v100 \T:=2.713,fine,tool0;
        MoveAbsJ zc_t15,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t16,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t17,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal check: pose 39 of 43, captured from below, then from above
        MoveAbsJ zc_t18,v100 \T:=4.109,fine,tool0;
        MoveAbsJ zc_t19,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t20,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t21,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal: the check's poses done; the robot parks where the pendant went on the flange (tilted
        ! past its range) to take the pendant off
        MoveAbsJ zc_t22,v100 \T:=5.298,fine,tool0;
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
