MODULE Cell
    ! Written for the test (issue 28): bRecipeReady is set by T_RX and cleared here.
    PERS bool bRecipeReady := FALSE;
    VAR num divisor := 0;
    VAR num ratio := 0;

    PROC main()
        WaitUntil bRecipeReady;
        bRecipeReady := FALSE;
        ratio := 10 / divisor;
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            RETRY;
        ENDIF
    ENDPROC
ENDMODULE
