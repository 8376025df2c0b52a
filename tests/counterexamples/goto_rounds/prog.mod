MODULE GotoLoop
    ! A reconnect loop made of a GOTO: each round counts a try, waits and asks the sensor
    ! again; the sixth try writes past the end of the log of tries.
    VAR num tries := 0;
    VAR num tried_at{5};
    VAR string state := "idle";

    PROC main()
        state := "connecting";
    again:
        tries := tries + 1;
        tried_at{tries} := tries * 10;
        WaitTime 0.5;
        IF DInput(di_link) = 0 GOTO again;
        state := "connected";
    ENDPROC
ENDMODULE
