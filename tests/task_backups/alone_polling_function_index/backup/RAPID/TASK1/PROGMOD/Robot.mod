MODULE Robot
    ! Written for the test (issue 28): the robot polls the flag of the slot a function
    ! picks; the receiver task T_RX sets the flags and the robot clears them, so the loop's
    ! condition reads them as a WaitUntil does.  Pick runs once per test of the condition.
    PERS bool flags{2} := [FALSE, FALSE];
    VAR num calls := 0;
    VAR num share := 0;

    PROC main()
        WHILE TRUE DO
            calls := 0;
            WHILE flags{Pick()} = FALSE DO
                calls := 0;
                WaitTime 0.1;
            ENDWHILE
            flags{1} := FALSE;
            IF calls <> 1 share := 1 / 0;
        ENDWHILE
    ENDPROC

    FUNC num Pick()
        calls := calls + 1;
        RETURN 1;
    ENDFUNC
ENDMODULE
