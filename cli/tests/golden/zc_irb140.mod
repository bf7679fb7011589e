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
    ! reached with each joint moving J1+ J2+ J3+ J4+ J5+ J6+.
    ! Dwell 3.2 s at each capture: settling 1 s (stated default) + the pendant's 2 s still window + 2
    ! sensor periods.
    ! Predicted robot time 5.2 min (motion 99 s, dwell 83 s, remount 120 s, operator OKs 10 s).
    ! WARNING: the path is NOT checked for collisions with the cell, the pendant or its bracket. Check
    ! the cell, then step through the program once at reduced speed (T1) before running it.
    CONST jointtarget zc_t1:=[[-91.00000,-46.00000,-91.00000,-1.00000,-1.00000,-1.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t2:=[[-90.00000,-45.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t3:=[[-90.00000,0.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t4:=[[90.00000,0.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t5:=[[-91.00000,0.00000,9.62346,-174.09610,-35.18639,-7.31390],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t6:=[[-90.00000,0.00000,9.62346,-173.09610,-34.18639,-6.31390],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t7:=[[-90.00000,0.00000,9.62346,-173.09610,10.81361,-6.31390],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t8:=[[-90.00000,0.00000,26.91095,-95.30145,-101.26748,-116.74863],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t9:=[[-90.00000,0.00000,26.91095,-95.30145,-100.26748,-115.74863],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t10:=[[-90.00000,0.00000,-50.18758,59.10364,-111.38231,-325.98017],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t11:=[[-90.00000,0.00000,-49.18758,59.10364,-110.38231,-324.98017],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t12:=[[-90.00000,0.00000,-52.02176,-46.33951,-113.10290,-383.78188],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t13:=[[-90.00000,0.00000,-51.02176,-45.33951,-112.10290,-382.78188],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t14:=[[-90.00000,0.00000,-46.54148,-72.84376,-108.24256,-399.34175],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t15:=[[-90.00000,0.00000,-46.54148,-71.84376,-108.24256,-398.34175],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t16:=[[-90.00000,0.00000,-4.99607,-185.58058,-0.73479,-360.63729],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t17:=[[-90.00000,0.00000,-4.99607,-184.58058,-0.73479,-360.63729],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t18:=[[-90.00000,0.00000,-108.55392,-174.65050,-111.43455,-358.75517],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t19:=[[-90.00000,0.00000,-107.55392,-174.65050,-110.43455,-358.75517],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t20:=[[-90.00000,0.00000,-174.47259,-139.94807,9.15932,-221.07216],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t21:=[[-90.00000,0.00000,-173.47259,-139.94807,9.15932,-221.07216],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t22:=[[-90.00000,0.00000,-98.90005,7.30562,100.50799,-181.12087],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t23:=[[-90.00000,0.00000,-113.01034,66.65755,101.14067,-158.43765],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t24:=[[-90.00000,0.00000,-112.01034,66.65755,101.14067,-158.43765],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t25:=[[-90.00000,0.00000,-164.47992,144.50679,19.07856,-149.27930],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t26:=[[-90.00000,0.00000,-163.47992,144.50679,20.07856,-149.27930],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t27:=[[-90.00000,0.00000,-190.98411,87.27137,92.64228,-80.31312],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t28:=[[-90.00000,0.00000,-189.98411,88.27137,92.64228,-80.31312],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t29:=[[-90.00000,0.00000,-202.38012,2.40693,17.77758,-4.60206],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t30:=[[-90.00000,0.00000,-201.38012,3.40693,18.77758,-4.60206],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t31:=[[-90.00000,0.00000,-163.19225,-27.03756,-20.66036,27.29344],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t32:=[[-90.00000,0.00000,-163.19225,-26.03756,-19.66036,27.29344],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t33:=[[-90.00000,0.00000,-216.64874,80.62455,-103.78124,-125.34101],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t34:=[[-90.00000,0.00000,-215.64874,80.62455,-102.78124,-124.34101],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t35:=[[-90.00000,0.00000,-215.33648,75.75634,-111.55810,-126.78185],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t36:=[[-90.00000,0.00000,-215.33648,76.75634,-110.55810,-125.78185],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t37:=[[-90.00000,0.00000,-114.22911,133.85536,-105.55015,-17.18325],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t38:=[[-90.00000,0.00000,-102.81475,193.64418,-101.33115,3.51614],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t39:=[[-90.00000,0.00000,-37.12500,79.57176,-113.43733,58.66790],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t40:=[[-90.00000,0.00000,-37.12500,80.57176,-112.43733,58.66790],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t41:=[[-90.00000,0.00000,-5.22760,85.86672,-48.11947,94.91882],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t42:=[[-90.00000,0.00000,27.57579,87.92430,-97.41158,116.78849],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t43:=[[-90.00000,0.00000,27.57579,87.92430,-96.41158,116.78849],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t44:=[[-90.00000,0.00000,37.87155,-93.41027,-102.50089,226.05810],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t45:=[[-90.00000,0.00000,37.87155,-92.41027,-101.50089,226.05810],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t46:=[[-90.00000,0.00000,-38.82741,-2.88995,35.23169,182.93335],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t47:=[[-90.00000,0.00000,-37.82741,-2.88995,35.23169,183.93335],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t48:=[[-90.00000,0.00000,42.26502,-71.74917,109.81420,312.84353],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t49:=[[-90.00000,0.00000,42.26502,-70.74917,109.81420,312.84353],[9E9,9E9,9E9,9E9,9E9,9E9]];
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
        ! zerocal stage 2: pose 1 of 24
        MoveAbsJ zc_t7,v100 \T:=1.774,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 2 of 24
        MoveAbsJ zc_t8,v100 \T:=3.637,fine,tool0;
        MoveAbsJ zc_t9,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 3 of 24
        MoveAbsJ zc_t10,v100 \T:=5.326,fine,tool0;
        MoveAbsJ zc_t11,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 4 of 24
        MoveAbsJ zc_t12,v100 \T:=3.453,fine,tool0;
        MoveAbsJ zc_t13,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 5 of 24
        MoveAbsJ zc_t14,v100 \T:=1.288,fine,tool0;
        MoveAbsJ zc_t15,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 6 of 24
        MoveAbsJ zc_t16,v100 \T:=3.683,fine,tool0;
        MoveAbsJ zc_t17,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 7 of 24
        MoveAbsJ zc_t18,v100 \T:=4.361,fine,tool0;
        MoveAbsJ zc_t19,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 8 of 24
        MoveAbsJ zc_t20,v100 \T:=3.846,fine,tool0;
        MoveAbsJ zc_t21,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 9 of 24
        MoveAbsJ zc_t22,v100 \T:=4.614,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 10 of 24
        MoveAbsJ zc_t23,v100 \T:=2.172,fine,tool0;
        MoveAbsJ zc_t24,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 11 of 24
        MoveAbsJ zc_t25,v100 \T:=2.803,fine,tool0;
        MoveAbsJ zc_t26,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 12 of 24
        MoveAbsJ zc_t27,v100 \T:=2.539,fine,tool0;
        MoveAbsJ zc_t28,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 13 of 24
        MoveAbsJ zc_t29,v100 \T:=2.909,fine,tool0;
        MoveAbsJ zc_t30,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 14 of 24
        MoveAbsJ zc_t31,v100 \T:=1.847,fine,tool0;
        MoveAbsJ zc_t32,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 15 of 24
        MoveAbsJ zc_t33,v100 \T:=4.046,fine,tool0;
        MoveAbsJ zc_t34,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 16 of 24
        MoveAbsJ zc_t35,v100 \T:=0.715,fine,tool0;
        MoveAbsJ zc_t36,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 17 of 24
        MoveAbsJ zc_t37,v100 \T:=4.267,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 18 of 24
        MoveAbsJ zc_t38,v100 \T:=2.184,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 19 of 24
        MoveAbsJ zc_t39,v100 \T:=3.692,fine,tool0;
        MoveAbsJ zc_t40,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 20 of 24
        MoveAbsJ zc_t41,v100 \T:=2.310,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 21 of 24
        MoveAbsJ zc_t42,v100 \T:=1.893,fine,tool0;
        MoveAbsJ zc_t43,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 22 of 24
        MoveAbsJ zc_t44,v100 \T:=5.561,fine,tool0;
        MoveAbsJ zc_t45,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 23 of 24
        MoveAbsJ zc_t46,v100 \T:=4.322,fine,tool0;
        MoveAbsJ zc_t47,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 24 of 24
        MoveAbsJ zc_t48,v100 \T:=3.519,fine,tool0;
        MoveAbsJ zc_t49,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal: session done; the pendant shows the result
    ENDPROC
ENDMODULE
