MODULE InterruptAlarm
    ! A rising edge on the free input DI_ALARM runs the TRAP OnAlarm.
    VAR intnum alarm_int;
    VAR signaldi alarm;
    VAR bool alarmed := FALSE;

    PROC main()
        AliasIO "DI_ALARM", alarm;
        CONNECT alarm_int WITH OnAlarm;
        ISignalDI alarm, 1, alarm_int;
        WHILE TRUE DO
            WaitTime 1;
        ENDWHILE
    ENDPROC

    TRAP OnAlarm
        alarmed := TRUE;
    ENDTRAP
ENDMODULE
