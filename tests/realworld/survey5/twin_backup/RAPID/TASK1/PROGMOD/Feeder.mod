MODULE Feeder
    ! Motion task: hands three parts to the counting task through a PERS flag.
    ! The recipe input of the I/O configuration is meant for a later version.
    PERS bool bPartReady := FALSE;
    PERS num nPartsFed := 0;
    PERS num nPartsTaken;

    PROC main()
        WHILE nPartsFed < 3 DO
            WaitUntil NOT bPartReady;
            IF giPartType = 2 THEN
                Set doDiverter;
            ELSE
                Reset doDiverter;
            ENDIF
            nPartsFed := nPartsFed + 1;
            bPartReady := TRUE;
        ENDWHILE
    ENDPROC
ENDMODULE
