MODULE Cell
    ! The main task counts parts; the watcher task orders the interrupt.
    PERS num counted := 0;
    PERS bool stopped := FALSE;

    PROC main()
        WHILE counted < 3 DO
            WaitDI diStart, 1;
            IF DInput(diPart) = 1 THEN
                counted := counted + 1;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
