MODULE Logger
    ! Written for the test (issue 28): the logger divides by a count it never set once a
    ! command is there, a defect reached only after robot 1's wait took the command. The
    ! reduction must not take the logger's read as independent of that wait.
    PERS string stCmd := "";
    VAR num nTaken := 0;
    VAR num share := 0;

    PROC main()
        IF stCmd <> "" THEN
            share := 100 / nTaken;
        ENDIF
    ENDPROC
ENDMODULE
