MODULE AtomsBareNames
    ! A configured output used by name, a signaldo bound late, a bool flag.
    VAR signaldo lamp;
    VAR bool armed := FALSE;

    PROC main()
        SetDO do_horn, 1;
        AliasIO "DO_LAMP", lamp;
        SetDO lamp, 1;
        armed := TRUE;
    ENDPROC
ENDMODULE
