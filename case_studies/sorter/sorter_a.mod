MODULE MainModule
    ! Program A of the K-RAPID paper (appendix A.1): the correct sorter.
    ! Changes against the printed listing are listed in README.md.

    ! Define the target positions of robot.
    VAR robtarget a := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR robtarget b := [[700, -300, 150], [0, 0, 1, 0], [-1, 0, -1, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR robtarget c1 := [[300, 600, 150], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR robtarget c2 := [[-300, 600, 150], [0, 0, 1, 0], [1, 0, 1, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

    ! Define the speed of the robot.
    VAR speeddata v := [1000, 500, 5000, 1000];

    ! Define the zonedata of the robot.
    VAR zonedata zone := [FALSE, 10, 15, 15, 1.5, 15, 1.5];

    ! Define the end effector of the robot.
    PERS tooldata gripper := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];

    ! Declare the I/O signals.
    VAR signaldi s1;
    VAR signaldi s2;
    VAR signaldi s3;
    VAR signaldi s4;
    VAR signaldi c_in;
    VAR signaldo c_out;
    VAR signaldo do_grip;

    ! Define the I/O units.
    CONST string config_cin := "C_IN";
    CONST string config_cout := "C_OUT";
    CONST string config_s1 := "S_1";
    CONST string config_s2 := "S_2";
    CONST string config_s3 := "S_3";
    CONST string config_s4 := "S_4";
    CONST string config_grip := "GRIPPER";

    PROC main()
        VAR bool flag_1 := false;
        VAR bool flag_2 := false;
        VAR bool flag_3 := false;
        VAR bool flag_4 := false;

        ! Link the I/O units with the I/O variables.
        AliasIO config_cin, c_in;
        AliasIO config_cout, c_out;
        AliasIO config_s1, s1;
        AliasIO config_s2, s2;
        AliasIO config_s3, s3;
        AliasIO config_s4, s4;
        AliasIO config_grip, do_grip;

        WHILE true DO
            ! Transport the non-defective pinions
            ! and restart the conveyor.
            flag_1 := c_in=0 AND s1=1 AND s2=1;
            IF flag_1 THEN
                MoveJ b, v, zone, gripper;
                Grip;
                MoveJ c1, v, zone, gripper;
                Drop;
                MoveJ a, v, zone, gripper;
                flag_3 := (s3 = 1) AND (s4 = 0);
                IF flag_3 THEN
                    SetDO c_out, 1;
                ENDIF
            ENDIF

            ! Transport the defective pinions
            ! and restart the conveyor.
            ! RAPID's NOT has the lowest priority: this reads
            ! c_in=0 AND NOT (s1=1 AND s2=1), "some sensor rejected the pinion".
            flag_2 := c_in=0 AND NOT s1=1 AND s2=1;
            IF flag_2 THEN
                MoveJ b, v, zone, gripper;
                Grip;
                MoveJ c2, v, zone, gripper;
                Drop;
                MoveJ a, v, zone, gripper;
                flag_4 := (s3 = 0) AND (s4 = 1);
                IF flag_4 THEN
                    SetDO c_out, 1;
                ENDIF
            ENDIF
        ENDWHILE
    ENDPROC

    ! Grip the pinions.
    PROC Grip()
        SetDO do_grip, 1;
    ENDPROC

    ! Drop the pinions.
    PROC Drop()
        SetDO do_grip, 0;
    ENDPROC
ENDMODULE
