MODULE RetryDivisor
    ! A division by an input value; the ERROR handler replaces a zero
    ! divisor by 1 and retries the division.
    VAR num divisor := 0;
    VAR num ratio := 0;

    PROC main()
        divisor := DInput(di_count);
        ratio := 10 / divisor;
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            divisor := 1;
            RETRY;
        ENDIF
    ENDPROC
ENDMODULE
