MODULE RetryInLoop
    ! In every pass a division by an input value; the handler replaces a
    ! zero divisor by 1 and retries.
    VAR num divisor := 0;
    VAR num ratio := 0;

    PROC main()
        WHILE TRUE DO
            divisor := DInput(di_count);
            ratio := 10 / divisor;
        ENDWHILE
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            divisor := 1;
            RETRY;
        ENDIF
    ENDPROC
ENDMODULE
