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
    ! Predicted robot time 5.4 min (motion 112 s, dwell 83 s, remount 120 s, operator OKs 10 s).
    ! WARNING: the path is NOT checked for collisions with the cell, the pendant or its bracket. Check
    ! the cell, then step through the program once at reduced speed (T1) before running it.
    CONST jointtarget zc_t1:=[[-91.00000,-46.00000,-91.00000,-1.00000,-1.00000,-1.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t2:=[[-90.00000,-45.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t3:=[[-90.00000,0.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t4:=[[90.00000,0.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t5:=[[-91.00000,0.00000,-99.90005,7.30562,55.50799,-182.12087],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t6:=[[-90.00000,0.00000,-98.90005,7.30562,55.50799,-181.12087],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t7:=[[-90.00000,0.00000,-98.90005,7.30562,100.50799,-181.12087],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t8:=[[-90.00000,0.00000,-190.98411,88.27137,91.64228,-80.31312],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t9:=[[-90.00000,0.00000,-189.98411,88.27137,92.64228,-80.31312],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t10:=[[-90.00000,0.00000,-202.38012,2.40693,17.77758,-4.60206],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t11:=[[-90.00000,0.00000,-201.38012,3.40693,18.77758,-4.60206],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t12:=[[-90.00000,0.00000,-163.19225,-27.03756,-20.66036,27.29344],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t13:=[[-90.00000,0.00000,-163.19225,-26.03756,-19.66036,27.29344],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t14:=[[-90.00000,0.00000,-37.12500,80.57176,-113.43733,58.66790],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t15:=[[-90.00000,0.00000,-37.12500,80.57176,-112.43733,58.66790],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t16:=[[-90.00000,0.00000,-115.22911,133.85536,-105.55015,-18.18325],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t17:=[[-90.00000,0.00000,-114.22911,133.85536,-105.55015,-17.18325],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t18:=[[-90.00000,0.00000,-102.81475,193.64418,-101.33115,3.51614],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t19:=[[-90.00000,0.00000,-219.04166,165.43498,-40.14653,-166.34977],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t20:=[[-90.00000,0.00000,-218.04166,166.43498,-40.14653,-165.34977],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t21:=[[-90.00000,0.00000,-215.64874,79.62455,-103.78124,-124.34101],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t22:=[[-90.00000,0.00000,-215.64874,80.62455,-102.78124,-124.34101],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t23:=[[-90.00000,0.00000,-209.03460,-82.84164,-110.49098,-237.67092],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t24:=[[-90.00000,0.00000,-209.03460,-81.84164,-109.49098,-236.67092],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t25:=[[-90.00000,0.00000,-173.47259,-140.94807,9.15932,-221.07216],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t26:=[[-90.00000,0.00000,-173.47259,-139.94807,9.15932,-221.07216],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t27:=[[-90.00000,0.00000,-46.54148,-71.84376,-109.24256,-399.34175],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t28:=[[-90.00000,0.00000,-46.54148,-71.84376,-108.24256,-398.34175],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t29:=[[-90.00000,0.00000,-29.45066,81.51550,-110.35571,-298.42501],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t30:=[[-90.00000,0.00000,-29.45066,81.51550,-109.35571,-298.42501],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t31:=[[-90.00000,0.00000,34.95577,-34.25351,-32.98967,-150.28211],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t32:=[[-90.00000,0.00000,34.95577,-33.25351,-32.98967,-150.28211],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t33:=[[-90.00000,0.00000,25.91095,-96.30145,-101.26748,-115.74863],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t34:=[[-90.00000,0.00000,26.91095,-95.30145,-100.26748,-115.74863],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t35:=[[-90.00000,0.00000,-66.54218,-100.66588,-93.24952,-31.03582],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t36:=[[-90.00000,0.00000,-65.54218,-99.66588,-93.24952,-31.03582],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t37:=[[-90.00000,0.00000,-34.11984,-192.50689,-35.33136,8.08573],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t38:=[[-90.00000,0.00000,-34.11984,-191.50689,-35.33136,8.08573],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t39:=[[-90.00000,0.00000,9.62346,-173.09610,10.81361,-7.31390],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t40:=[[-90.00000,0.00000,9.62346,-173.09610,10.81361,-6.31390],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t41:=[[-90.00000,0.00000,46.86624,-116.49662,-114.32392,215.90720],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t42:=[[-90.00000,0.00000,46.86624,-116.49662,-113.32392,215.90720],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t43:=[[-90.00000,0.00000,-45.37156,-99.44739,-82.41241,316.67759],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t44:=[[-90.00000,0.00000,-44.37156,-99.44739,-82.41241,316.67759],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t45:=[[-90.00000,0.00000,-178.12677,95.35289,-55.35020,261.61964],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t46:=[[-90.00000,0.00000,-177.12677,95.35289,-55.35020,262.61964],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t47:=[[-90.00000,0.00000,-64.97476,-61.55644,79.33036,200.07668],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t48:=[[-90.00000,0.00000,-64.97476,-60.55644,79.33036,201.07668],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t49:=[[-90.00000,0.00000,-45.90816,-92.86208,90.87796,219.67238],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t50:=[[-90.00000,0.00000,-45.90816,-91.86208,90.87796,219.67238],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t51:=[[-90.00000,0.00000,42.26502,-70.74917,109.81420,312.84353],[9E9,9E9,9E9,9E9,9E9,9E9]];
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
        MoveAbsJ zc_t8,v100 \T:=3.920,fine,tool0;
        MoveAbsJ zc_t9,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 3 of 24
        MoveAbsJ zc_t10,v100 \T:=2.909,fine,tool0;
        MoveAbsJ zc_t11,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 4 of 24
        MoveAbsJ zc_t12,v100 \T:=1.847,fine,tool0;
        MoveAbsJ zc_t13,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 5 of 24
        MoveAbsJ zc_t14,v100 \T:=5.227,fine,tool0;
        MoveAbsJ zc_t15,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 6 of 24
        MoveAbsJ zc_t16,v100 \T:=3.382,fine,tool0;
        MoveAbsJ zc_t17,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 7 of 24
        MoveAbsJ zc_t18,v100 \T:=2.184,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 8 of 24
        MoveAbsJ zc_t19,v100 \T:=4.848,fine,tool0;
        MoveAbsJ zc_t20,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 9 of 24
        MoveAbsJ zc_t21,v100 \T:=2.935,fine,tool0;
        MoveAbsJ zc_t22,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 10 of 24
        MoveAbsJ zc_t23,v100 \T:=5.064,fine,tool0;
        MoveAbsJ zc_t24,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 11 of 24
        MoveAbsJ zc_t25,v100 \T:=3.819,fine,tool0;
        MoveAbsJ zc_t26,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 12 of 24
        MoveAbsJ zc_t27,v100 \T:=5.260,fine,tool0;
        MoveAbsJ zc_t28,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 13 of 24
        MoveAbsJ zc_t29,v100 \T:=4.784,fine,tool0;
        MoveAbsJ zc_t30,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 14 of 24
        MoveAbsJ zc_t31,v100 \T:=3.947,fine,tool0;
        MoveAbsJ zc_t32,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 15 of 24
        MoveAbsJ zc_t33,v100 \T:=2.420,fine,tool0;
        MoveAbsJ zc_t34,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 16 of 24
        MoveAbsJ zc_t35,v100 \T:=3.973,fine,tool0;
        MoveAbsJ zc_t36,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 17 of 24
        MoveAbsJ zc_t37,v100 \T:=3.103,fine,tool0;
        MoveAbsJ zc_t38,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 18 of 24
        MoveAbsJ zc_t39,v100 \T:=2.061,fine,tool0;
        MoveAbsJ zc_t40,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 19 of 24
        MoveAbsJ zc_t41,v100 \T:=5.593,fine,tool0;
        MoveAbsJ zc_t42,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 20 of 24
        MoveAbsJ zc_t43,v100 \T:=3.926,fine,tool0;
        MoveAbsJ zc_t44,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 21 of 24
        MoveAbsJ zc_t45,v100 \T:=5.935,fine,tool0;
        MoveAbsJ zc_t46,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 22 of 24
        MoveAbsJ zc_t47,v100 \T:=4.882,fine,tool0;
        MoveAbsJ zc_t48,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 23 of 24
        MoveAbsJ zc_t49,v100 \T:=1.421,fine,tool0;
        MoveAbsJ zc_t50,v100 \T:=0.241,fine,tool0;
        WaitTime 3.200;
        ! zerocal stage 2: pose 24 of 24
        MoveAbsJ zc_t51,v100 \T:=3.769,fine,tool0;
        WaitTime 3.200;
        ! zerocal: session done; the pendant shows the result
    ENDPROC
ENDMODULE
