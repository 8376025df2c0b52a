MODULE RetryLoop
    ! A gripper that never closes: the retry loop runs five times, then the program stops
    ! on an uncaught error.
    VAR num attempts := 0;
    VAR bool closed := FALSE;

    PROC main()
        Grip;
    ENDPROC

    PROC Grip()
        attempts := attempts + 1;
        SetDO do_close, 1;
        WaitDI di_closed, 1 \MaxTime:=2;
        closed := TRUE;
    ERROR
        IF ERRNO = ERR_WAIT_MAXTIME THEN
            SetDO do_close, 0;
            RETRY;
        ENDIF
    ENDPROC
ENDMODULE
