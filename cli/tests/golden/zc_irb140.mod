%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE ZC_IRB140
    ! zerocal robot program: a joint-zero calibration session.
    ! Robot ABB IRB 140T-6/0.81 (IRB 140T; ROS-I model irb140t_6_81) (profile abb-irb140); 8 stage-2
    ! poses. Written by zerocal 0.1.0; targets in the controller's joint degrees.
    ! Stop: clip the pendant to the upper arm (the robot stands with the pendant tilted past its
    ! range, so it cannot capture early). Stage 1: the stage-1 pose, then joint 1 turned by 180 deg
    ! (an OK on the pendant takes that reading). Stop: joint 1 back, clip the pendant to the flange
    ! (tilted again). Stage 2: the plan's poses in its order; load the same plan into the pendant
    ! (plan set).
    ! Speed: joint moves at 10 % of each joint's maximum speed, exact stops. Backlash: every target is
    ! reached with each joint moving J1+ J2+ J3+ J4+ J5+ J6+.
    ! Dwell 3.2 s at each capture: settling 1 s (stated default) + the pendant's 2 s still window + 2
    ! sensor periods.
    ! Predicted robot time 3.8 min (motion 64 s, dwell 32 s, remount 120 s, operator OKs 10 s).
    ! WARNING: the path is NOT checked for collisions with the cell, the pendant or its bracket. Check
    ! the cell, then step through the program once at reduced speed (T1) before running it.
    CONST jointtarget zc_t1:=[[-91.00000,-46.00000,-91.00000,-1.00000,-1.00000,-1.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t2:=[[-90.00000,-45.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t3:=[[-90.00000,0.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t4:=[[90.00000,0.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t5:=[[-91.00000,0.00000,-202.22233,-171.87146,16.49433,-271.57527],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t6:=[[-90.00000,0.00000,-201.22233,-170.87146,16.49433,-270.57527],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t7:=[[-90.00000,0.00000,-201.22233,-170.87146,61.49433,-270.57527],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t8:=[[-90.00000,0.00000,-168.28733,-168.60248,102.82457,-224.78407],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t9:=[[-90.00000,0.00000,-25.12160,-7.68315,106.11683,-96.24878],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t10:=[[-90.00000,0.00000,-1.48463,-12.91873,91.02342,-309.54523],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t11:=[[-90.00000,0.00000,-1.48463,-11.91873,92.02342,-308.54523],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t12:=[[-90.00000,0.00000,-202.68128,171.38509,74.03093,-184.25051],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t13:=[[-90.00000,0.00000,-201.68128,171.38509,75.03093,-184.25051],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t14:=[[-90.00000,0.00000,-223.89861,-18.02717,-44.11531,-57.38956],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t15:=[[-90.00000,0.00000,-222.89861,-17.02717,-43.11531,-57.38956],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t16:=[[-90.00000,0.00000,-214.16638,-8.32206,-64.13785,184.59342],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t17:=[[-90.00000,0.00000,-214.16638,-8.32206,-63.13785,184.59342],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t18:=[[-90.00000,0.00000,46.31577,191.64337,-50.10609,276.20128],[9E9,9E9,9E9,9E9,9E9,9E9]];
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
        WaitTime 3.200;
        ! zerocal stage 1: joint 1 turned by 180 deg
        MoveAbsJ zc_t4,v100 \T:=7.564,fine,tool0;
        WaitTime 3.200;
        TPWrite "zerocal: press OK on the pendant, wait";
        TPWrite "for its POSE screen, then continue.";
        STOP;
        ! zerocal: joint 1 back; the pendant goes on the flange here, tilted past its range
        MoveAbsJ zc_t5,v100 \T:=7.604,fine,tool0;
        MoveAbsJ zc_t6,v100 \T:=0.241,fine,tool0;
        TPWrite "zerocal: clip the pendant to the flange";
        TPWrite "(its screen at POSE 1), then continue.";
        STOP;
        ! zerocal stage 2: pose 1 of 8
        MoveAbsJ zc_t7,v100 \T:=1.774,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 2 of 8
        MoveAbsJ zc_t8,v100 \T:=1.672,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 3 of 8
        MoveAbsJ zc_t9,v100 \T:=5.885,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 4 of 8
        MoveAbsJ zc_t10,v100 \T:=5.394,fine,tool0;
        MoveAbsJ zc_t11,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 5 of 8
        MoveAbsJ zc_t12,v100 \T:=8.116,fine,tool0;
        MoveAbsJ zc_t13,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 6 of 8
        MoveAbsJ zc_t14,v100 \T:=5.785,fine,tool0;
        MoveAbsJ zc_t15,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 7 of 8
        MoveAbsJ zc_t16,v100 \T:=6.032,fine,tool0;
        MoveAbsJ zc_t17,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 8 of 8
        MoveAbsJ zc_t18,v100 \T:=10.397,fine,tool0;
        WaitTime 3.200;
        ! zerocal: session done; the pendant shows the result
    ENDPROC
ENDMODULE
