! expect: RMC006 line 1
! nothing but comments here
!MODULE m
!ENDMODULE
