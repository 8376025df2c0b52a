MODULE WaitMaxTimeError
    ! Waits at most 2 s for di_ready; without \TimeFlag a timeout is an error.
    VAR bool ready := FALSE;

    PROC main()
        WaitUntil DInput(di_ready) = 1 \MaxTime:=2;
        ready := TRUE;
    ENDPROC
ENDMODULE
