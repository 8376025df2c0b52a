MODULE clamp_library
    ! Survey round 7: a gripper library whose data types live in a module that was not
    ! given. The declarations' values show them: an aggregate of atomic parts is a RECORD
    ! of those parts' types, a single number makes the type an ALIAS of num.
    PERS jawdata jawFront := ["front jaws", 3, TRUE, FALSE];
    PERS jawdata jawBack := ["back jaws", 1, FALSE, FALSE];
    CONST stationno stGripper := 4;
    PERS num nSelected := 0;

    PROC main()
        jawActive := jawBack;
        nSelected := stGripper;
        ReportJaws jawActive;
    ENDPROC
ENDMODULE
