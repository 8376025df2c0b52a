MODULE TrajectoryFollower
    ! A YuMi arm that replays joint points a ROS driver task writes into shared data
    ! (the trajectory buffers and their record type live in the driver's module, which
    ! is not given here). Written for rapidmc's survey round 5.
    LOCAL VAR Arm_point current_pt;
    LOCAL VAR num last_width := -1;
    LOCAL CONST num WIDTH_BAND := 1.5;

    PROC main()
        VAR jointtarget goal;
        Hand_Initialize \Calibrate;
        Hand_MoveTo 0;
        Hand_WaitMovingCompleted;
        FOR k FROM 1 TO 2 DO
            IF Abs(finger_buffer{k}.width - last_width) > WIDTH_BAND THEN
                Hand_MoveTo finger_buffer{k}.width \NoWait;
                last_width := finger_buffer{k}.width;
            ENDIF
            current_pt := arm_buffer{k};
            goal := current_pt.joints;
            MoveAbsJ goal, v200, fine, tool0;
            Hand_WaitMovingCompleted;
        ENDFOR
        new_points := FALSE;
    ENDPROC
ENDMODULE
