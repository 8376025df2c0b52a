MODULE InputConfiguredLamp
    ! Signals of the I/O configuration used by name, without declarations:
    ! the lamp shows the last value read from di_start.
    PROC main()
        WHILE TRUE DO
            IF DInput(di_start) = 1 THEN
                SetDO do_lamp, 1;
            ELSE
                SetDO do_lamp, 0;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
