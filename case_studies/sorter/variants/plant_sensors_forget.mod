MODULE SorterPlant
    ! VARIANT of ../plant.mod, kept to show how a small modelling choice flips
    ! verdicts (see ../README.md, "Modelling choices"): the inspection sensors
    ! S_1/S_2 drop to 0 when the pinion leaves zone B.
    !
    ! rapidmc runs react() to completion after every step of the program
    ! (synchronous composition).  One reaction does, in this order:
    !   1. a running Conveyor1 may deliver a pinion to zone B,
    !   2. the gripper takes the pinion at B, or releases it at C1 or C2,
    !   3. Conveyor1 restarts if the robot commands it and zone B is clear.

    ! Bound by name to the physical signals the programs bind with AliasIO.
    ! signaldi: an input of the program, driven here; signaldo: read here.
    VAR signaldi C_IN;      ! Conveyor1 motor status, 1 = running
    VAR signaldi S_1;       ! vision sensor, 1 = the pinion passed
    VAR signaldi S_2;       ! weight sensor, 1 = the pinion passed
    VAR signaldi S_3;       ! 1 = the last pinion went to C1 (Conveyor2)
    VAR signaldi S_4;       ! 1 = the last pinion went to C2 (Conveyor3)
    VAR signaldo C_OUT;     ! the robot's command to Conveyor1, 1 = run
    VAR signaldo GRIPPER;   ! the robot's gripper, 1 = closed

    ! Where the cell's places are: the TCP positions of the programs'
    ! targets b, c1 and c2 (the plant has its own namespace).
    CONST pos ZONE_B := [700, -300, 150];
    CONST pos PLACE_C1 := [300, 600, 150];
    CONST pos PLACE_C2 := [-300, 600, 150];

    VAR bool pinion_in_zone_b := FALSE;
    VAR bool pinion_in_gripper := FALSE;

    ! Initially Conveyor1 runs, zone B is empty and every sensor reads 0.
    PROC init()
        SetDI C_IN, 1;
    ENDPROC

    PROC react()
        DeliverPinion;
        MoveGripper;
        RestartConveyor1;
    ENDPROC

    ! A running Conveyor1 may bring a pinion to zone B, or not (arrivals may
    ! stop for ever).  The pinion stops the belt and both sensors report their
    ! verdicts in the same reaction, so the program never sees a stopped belt
    ! with a pinion the sensors have not judged yet.
    PROC DeliverPinion()
        IF C_IN = 1 THEN
            IF AnyBool() THEN
                pinion_in_zone_b := TRUE;
                SetDI C_IN, 0;
                SetDI S_1, AnyNum(0, 1);
                SetDI S_2, AnyNum(0, 1);
            ENDIF
        ENDIF
    ENDPROC

    ! Closing the gripper at B takes the waiting pinion out of zone B.
    ! Opening it drops the pinion where the robot is: S_3/S_4 report a drop
    ! onto Conveyor2 (C1) or Conveyor3 (C2); anywhere else no sensor sees it.
    ! S_1/S_2 keep their verdicts and S_3/S_4 keep showing where the last
    ! pinion went until the next event that changes them.
    PROC MoveGripper()
        IF DOutput(GRIPPER) = 1 THEN
            IF pinion_in_zone_b AND RobotAt(ZONE_B) AND (NOT pinion_in_gripper) THEN
                pinion_in_zone_b := FALSE;
                pinion_in_gripper := TRUE;
                SetDI S_1, 0;
                SetDI S_2, 0;
            ENDIF
        ELSEIF pinion_in_gripper THEN
            pinion_in_gripper := FALSE;
            IF RobotAt(PLACE_C1) THEN
                SetDI S_3, 1;
                SetDI S_4, 0;
            ELSEIF RobotAt(PLACE_C2) THEN
                SetDI S_3, 0;
                SetDI S_4, 1;
            ENDIF
        ENDIF
    ENDPROC

    ! Conveyor1 runs while the robot commands it (C_OUT = 1), except that a
    ! pinion in zone B stops it.  The programs never reset C_OUT, so from the
    ! second pinion on the belt restarts as soon as the robot lifts a pinion.
    PROC RestartConveyor1()
        IF C_IN = 0 AND DOutput(C_OUT) = 1 AND (NOT pinion_in_zone_b) THEN
            SetDI C_IN, 1;
        ENDIF
    ENDPROC

    FUNC bool RobotAt(pos place)
        RETURN Distance(CPos(), place) < 1;
    ENDFUNC
ENDMODULE
