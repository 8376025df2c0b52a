MODULE UnsetRetryMax
    ! Issue 28, a true defect that must stay found: the handler retries a division whose
    ! divisor it never repairs; after the controller's retry limit the task stops with
    ! ERR_EXCRTYMAX. The recipe comes from a PC; its flag and factor are declared without a value.
    PERS bool bRecipeReady;
    PERS num nFactor;
    VAR num divisor := 0;
    VAR num ratio := 0;

    PROC main()
        WaitUntil bRecipeReady;
        ratio := nFactor / divisor;
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            RETRY;
        ENDIF
    ENDPROC
ENDMODULE
