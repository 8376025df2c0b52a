MODULE VmWhileAnalog
    ! A WHILE whose condition reads a free input; an analog input with a
    ! fractional domain (values are nums: float32); a FOR whose TO divides by
    ! a value that may be 0, the error handled with TRYNEXT.
    VAR signalai level;
    VAR num reading := 0;
    VAR num tenfold := 0;
    VAR num spins := 0;
    VAR num count := 0;
    VAR num width := 0;
    VAR num skipped := 0;

    PROC main()
        AliasIO "AI_LEVEL", level;
        WHILE TRUE DO
            spins := 0;
            WHILE DInput(di_run) = 1 AND spins < 2 DO
                spins := spins + 1;
            ENDWHILE
            reading := AInput(level);
            tenfold := reading * 10;
            width := Trunc(reading);
            count := 0;
            FOR k FROM 1 TO 3 / width DO
                count := count + 1;
            ENDFOR
        ENDWHILE
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            skipped := 1;
            count := -1;
            TRYNEXT;
        ENDIF
        RAISE;
    ENDPROC
ENDMODULE
