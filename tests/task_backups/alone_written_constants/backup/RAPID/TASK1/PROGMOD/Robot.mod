MODULE Robot
    ! Written for the test (issue 28): the robot task counts the seams it welds in a
    ! shared PERS, 0 between jobs; it writes constants and a FOR loop's count only.
    PERS num nStep{2};
    VAR num nSeams := 3;

    PROC main()
        nStep{1} := 0;
        FOR i FROM 1 TO nSeams DO
            nStep{1} := i;
            WaitTime 1;
        ENDFOR
        nStep{1} := 0;
        nStep{2} := 2;
    ENDPROC
ENDMODULE
