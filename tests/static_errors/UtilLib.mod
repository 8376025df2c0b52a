MODULE UtilLib
  ! Tests: a library without main names the procedures one could start from.
  PROC ResetCell()
  ENDPROC
  PROC MoveToSlot(num slot)
  ENDPROC
  LOCAL PROC Helper()
  ENDPROC
  PROC Service()
  ENDPROC
ENDMODULE
