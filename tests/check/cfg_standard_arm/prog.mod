MODULE CfgStandardArm
    ! Issue 19: the joint limits of a standard six-axis arm, read without an error
    ! handler. Every standard controller configures MOC/ARM rob1_1..rob1_6 with
    ! upper_joint_bound, so no ERR_CFG_NOTFND is reachable; the values are the
    ! controller's, so the data keep theirs (the RMC702 note says so).
    VAR num upper{6} := [1, 1, 1, 1, 1, 1];
    VAR string arm_type := "";

    PROC main()
        FOR i FROM 1 TO 6 DO
            ReadCfgData "MOC/ARM/rob1_" + NumToStr(i, 0), "upper_joint_bound", upper{i};
        ENDFOR
        ReadCfgData "/MOC/ROBOT/ROB_1", "use_robot_type", arm_type;
    ENDPROC
ENDMODULE
