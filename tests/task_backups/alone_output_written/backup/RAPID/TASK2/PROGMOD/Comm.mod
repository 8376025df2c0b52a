MODULE Comm
    ! Written for the test (issue 28): the communication task waits until the robot task
    ! has set its output, then counts its cycles into a log of three entries.
    VAR num log{3} := [0, 0, 0];
    VAR num entry := 0;

    PROC main()
        WaitUntil DOutput(doRobBusy) = 1;
        SetDO doCommReady, 1;
        WHILE DOutput(doRobBusy) = 1 DO
            entry := entry + 1;
            log{entry} := entry;
            WaitTime 0.1;
        ENDWHILE
    ENDPROC
ENDMODULE
